package tactus.haptics.inverse;

import java.io.IOException;
import java.net.URI;
import java.util.List;
import java.util.concurrent.locks.LockSupport;

import com.fasterxml.jackson.core.JsonFactory;

import tactus.haptics.safety.GuardMemory;
import tactus.haptics.safety.GuardProcess;

/**
 * The sketch's side of the {@link InverseGuard}: starts the guard process for a connection to the Inverse
 * Service, shares a {@link GuardMemory} with it, beats the heartbeat at every force sent (a memory store) and
 * every 5 ms from its own thread while a force is on, and says {@code clean} when the connection was closed
 * after zero force. Starting or talking to the guard never fails the device: a failure prints one warning.
 */
final class InverseGuardLink {
    /** System property that turns the guard off when "false" (default on). */
    static final String PROPERTY = "tactus.inverseGuard";
    /**
     * How long the sketch's JVM may give no heartbeat, while a force is on, before the guard zeroes it, in
     * milliseconds: as for the 2DIY's motor guard (a running JVM was seen to give none for up to 53 ms on the
     * loaded 2-core machine; see docs/haptics.md, "The motor guard").
     */
    static final int HEARTBEAT_STALE_MS = 100;
    /** How often the heartbeat thread beats while a force is on, in milliseconds. */
    static final int BEAT_MS = 5;
    /** The link of a device without a guard. */
    static final InverseGuardLink NONE = new InverseGuardLink(null, null);
    /**
     * The heartbeat thread's name: its first 15 characters are those of the 2DIY's torque watchdog, which is how
     * a guard on Linux finds the thread in {@code /proc} to tell a starved JVM from a paused one.
     */
    static final String BEAT_THREAD = "tactus-haply-torque-watchdog (Inverse3 heartbeat)";
    private static final String[] JVM_OPTIONS = {"-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC", "-Xms8m", "-Xmx48m",
            "-Xss512k", "-XX:-UsePerfData", "-Djava.awt.headless=true"};

    private final GuardProcess guard;
    private final GuardMemory memory;
    private volatile boolean armed;
    private volatile boolean released;

    private InverseGuardLink(GuardProcess guard, GuardMemory memory) {
        this.guard = guard;
        this.memory = memory;
    }

    /** True unless the property {@value #PROPERTY} is "false". */
    static boolean enabled() {
        return !"false".equalsIgnoreCase(System.getProperty(PROPERTY, "true"));
    }

    /**
     * Starts a guard for the Inverse3 with this id (null: the first listed) on the service at this address;
     * {@link #NONE} (with a warning) if it cannot.
     */
    static InverseGuardLink start(URI service, String deviceId) {
        GuardMemory memory;
        try {
            memory = GuardMemory.create();
        } catch (IOException | RuntimeException e) {
            System.err.println("Tactus: no shared memory for the Inverse3 guard (" + e + "); the force of a killed or "
                    + "paused sketch is left to the Inverse Service");
            return NONE;
        }
        try {
            InverseGuardLink link = new InverseGuardLink(GuardProcess.start(command(), "the Inverse3 guard"), memory);
            link.guard.send(InverseGuard.HELLO + "\nheartbeat " + HEARTBEAT_STALE_MS + " " + memory.path()
                    + (deviceId == null ? "" : "\ndevice " + deviceId) + "\nservice " + service);
            Thread beat = new Thread(link::beatWhileArmed, BEAT_THREAD);
            beat.setDaemon(true);
            beat.start();
            return link;
        } catch (IOException | RuntimeException e) {
            memory.unlink();
            System.err.println("Tactus: could not start the Inverse3 guard (" + e + "); the force of a killed or paused "
                    + "sketch is left to the Inverse Service");
            return NONE;
        }
    }

    /**
     * Waits up to ms for the guard to have its own session with the service (it keeps trying after a failed first
     * attempt); then removes the shared file's name. Returns true if the guard is ready.
     */
    boolean awaitReady(long ms) {
        if (memory == null) {
            return false;
        }
        long deadline = System.nanoTime() + ms * 1_000_000L;
        while (memory.state() != GuardMemory.STATE_READY && System.nanoTime() - deadline < 0 && guard.process().isAlive()) {
            LockSupport.parkNanos(2_000_000L);
        }
        memory.unlink();
        return memory.state() == GuardMemory.STATE_READY;
    }

    /** True if this link has a guard process. */
    boolean isGuarded() {
        return memory != null;
    }

    /**
     * A force was sent (the haptic thread): beats the heartbeat and says whether a force is on. Two memory
     * stores at most; no allocation.
     */
    void forceSent(double fx, double fy, double fz) {
        if (memory == null) {
            return;
        }
        memory.beat(System.nanoTime());
        boolean on = fx != 0 || fy != 0 || fz != 0;
        if (on != armed) {
            armed = on;
            memory.arm(on);
        }
    }

    /** How many times the guard has acted (a change means it zeroed the force while this JVM was paused). */
    long guardActs() {
        return memory == null ? 0 : memory.guardActs();
    }

    private void beatWhileArmed() {
        while (!released) {
            LockSupport.parkNanos(BEAT_MS * 1_000_000L);
            if (armed) {
                memory.beat(System.nanoTime());
            }
        }
    }

    /** Ends the link; with forceZeroed the guard exits at once, otherwise it zeroes the force itself now. */
    synchronized void release(boolean forceZeroed) {
        if (guard == null || released) {
            return;
        }
        released = true;
        armed = false;
        memory.arm(false);
        memory.unlink();
        if (forceZeroed) {
            guard.send("clean");
        }
        guard.closeInput();
    }

    /** The guard process, or null (for tests). */
    Process process() {
        return guard == null ? null : guard.process();
    }

    /** The guard's command line: this JVM's java, small-footprint options, Tactus and jackson-core. */
    static List<String> command() {
        return GuardProcess.command(InverseGuard.class.getName(), JVM_OPTIONS, new String[] {"java.io.tmpdir"},
                InverseGuard.class, GuardMemory.class, JsonFactory.class);
    }
}
