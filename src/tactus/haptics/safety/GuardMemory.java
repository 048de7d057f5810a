package tactus.haptics.safety;

import java.io.IOException;

/**
 * The memory a sketch's JVM shares with a guard process (a {@link GuardHeartbeat}), opened to Tactus's guards
 * outside this package: the Inverse3's guard ({@code tactus.haptics.inverse.InverseGuard}) uses it as the 2DIY's
 * {@link MotorGuard} does. The sketch's JVM stores a heartbeat and an armed flag (plain memory stores: no system
 * call, no lock, no allocation); the guard reads them, counts its own interventions and says its state. Not for
 * sketches.
 */
public final class GuardMemory {
    /** Guard state: not known yet. */
    public static final long STATE_WAITING = GuardHeartbeat.STATE_WAITING;
    /** Guard state: the guard is ready to act. */
    public static final long STATE_READY = GuardHeartbeat.STATE_READY;
    /** Guard state: the guard cannot act (for example, it could not reach what it guards). */
    public static final long STATE_UNABLE = GuardHeartbeat.STATE_NO_PORT;

    private final GuardHeartbeat memory;
    private final HeartbeatThreads threads;

    private GuardMemory(GuardHeartbeat memory, HeartbeatThreads threads) {
        this.memory = memory;
        this.threads = threads;
    }

    /** Creates the shared file (in {@code /dev/shm} where there is one) for the sketch's side. */
    public static GuardMemory create() throws IOException {
        return new GuardMemory(GuardHeartbeat.create(), null);
    }

    /**
     * Maps the file the sketch's JVM (process parentPid) created, for the guard's side; parentPid also lets the
     * guard tell a JVM that waits for a CPU from a paused one ({@link #parentWaitsForCpu()}).
     */
    public static GuardMemory open(String path, long parentPid) throws IOException {
        return new GuardMemory(GuardHeartbeat.open(path), new HeartbeatThreads(parentPid));
    }

    /** The shared file's path (before {@link #unlink()}). */
    public String path() {
        return memory.path();
    }

    /** Removes the file's name; both sides keep their mapping. */
    public void unlink() {
        memory.unlink();
    }

    /** Sketch side: a sign of life, the time now in nanoseconds. One memory store. */
    public void beat(long nanos) {
        memory.beat(nanos);
    }

    /** Sketch side: says whether a non-zero force is on (only then does the guard watch the heartbeat). */
    public void arm(boolean on) {
        memory.arm(on);
    }

    /** Sketch side: how many times the guard has acted. */
    public long guardActs() {
        return memory.guardWrites();
    }

    /** Sketch side: the guard's state ({@link #STATE_WAITING}, {@link #STATE_READY}, {@link #STATE_UNABLE}). */
    public long state() {
        return memory.state();
    }

    /** Guard side: the last heartbeat. */
    public long heartbeat() {
        return memory.heartbeat();
    }

    /** Guard side: true while the sketch says a non-zero force is on. */
    public boolean armed() {
        return memory.armed();
    }

    /** Guard side: counts one more intervention, before it is made. */
    public void countAct() {
        memory.countGuardWrite();
    }

    /** Guard side: sets the guard's state. */
    public void setState(long state) {
        memory.setState(state);
    }

    /**
     * Guard side, on Linux: true if a watchdog thread of the sketch's JVM (a thread named
     * {@code tactus-haply-torque-watchdog…}) is runnable, that is the JVM runs but waits for a CPU; false if it
     * sleeps or is stopped, or where nothing is known.
     */
    public boolean parentWaitsForCpu() {
        return threads != null && threads.waitForCpu();
    }

    /**
     * Guard side: ignores SIGINT, SIGTERM, SIGHUP and SIGTSTP, which a terminal or a service stop sends to the whole
     * process group: a guard must outlive the sketch (as the {@link MotorGuard} does).
     */
    public static void ignoreTerminalSignals() {
        MotorGuard.ignoreTerminalSignals();
    }
}
