package tactus.haptics.safety;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import tactus.haptics.Board;

/**
 * The motor guard: a small process that zeroes a Haply board's motors when the JVM driving them ends without
 * closing the board (the Processing editor's Stop button, which ends the sketch with {@code vm.exit(0)} over
 * JDWP and runs no shutdown hook; SIGKILL; {@code Runtime.halt}; a JVM crash). The firmware has no timeout and
 * keeps the last duty for good, so only a process outside that JVM can stop them.
 *
 * <p>A {@link Board} that opens a serial port starts it (see {@link Board#setMotorGuard(boolean)}) and tells it,
 * one line at a time on its standard input: {@code heartbeat <staleMs> <path>} (the memory it shares with the
 * board, a {@link GuardHeartbeat}); {@code port <baud> <name>}; {@code device <id> <writeBytes> <replyBytes>}
 * for each device set up (the length of its write message and of the board's reply); and {@code clean} when
 * the board was closed with the torques zeroed and answered.
 *
 * <p>While its parent lives, the guard only holds the port open for writing (opened on the {@code port} line,
 * before the board opens the port) and never reads it: when the parent's heartbeat stops for the stale time
 * while a torque is on (the JVM is paused: a debugger's breakpoint, SIGSTOP), it sends each device one write
 * with zero torques and zero PWM (see {@link MotorGuardPauseWatch}). When its standard input ends, or its
 * parent process is gone, without a {@code clean}, it opens the port, sends every device a write with zero
 * torques and zero PWM, waits up to 250 ms for the replies, sends a reset and exits. It does nothing if the
 * port's device node was replaced meanwhile (a pseudo-terminal freed and reused, a board plugged in again).
 * Every wait is bounded: the process halts at the latest 3 s after it started acting.
 */
public final class MotorGuard {
    /** First line the parent sends: names the protocol and its version. */
    static final String HELLO = "tactus-motor-guard 1";
    /** How long the guard may spend acting before it halts, in milliseconds. Not API: read by the board's tests. */
    public static final long ACT_LIMIT_MS = 3_000;
    private static final long PARENT_POLL_MS = 250;

    private final Map<Integer, int[]> devices = new LinkedHashMap<>();   // id -> {writeBytes, replyBytes}
    private String port;
    private int baud;
    private Object portIdentity;
    private boolean acted;
    private GuardHeartbeat heartbeat;
    private long staleMillis;
    private MotorGuardPauseWatch pauseWatch;

    private MotorGuard() {
    }

    /** Runs the guard: reads the parent's lines from standard input until it ends, then acts or exits. */
    public static void main(String[] args) {
        ignoreTerminalSignals();
        MotorGuard guard = new MotorGuard();
        Optional<ProcessHandle> parent = ProcessHandle.current().parent();
        Thread watcher = new Thread(() -> guard.watchParent(parent.orElse(null)), "tactus-motor-guard-parent");
        watcher.setDaemon(true);
        watcher.start();
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        try {
            String line;
            while ((line = in.readLine()) != null) {
                if (line.equals("clean")) {
                    System.exit(0);
                }
                guard.accept(line);
            }
        } catch (IOException e) {
            // the pipe broke: same as the parent gone
        }
        guard.act("the sketch's JVM ended (or released the board) without zeroing the motors");
    }

    /**
     * Ignores SIGINT, SIGTERM, SIGHUP and SIGTSTP: Ctrl-C or Ctrl-Z in a terminal, a closed terminal or a service
     * stop signal the whole process group, and the guard must outlive the sketch to do its job (it ends on its own once the
     * sketch is gone; SIGKILL still ends it).
     */
    static void ignoreTerminalSignals() {
        for (String name : new String[] {"INT", "TERM", "HUP", "TSTP"}) {
            try {
                sun.misc.Signal.handle(new sun.misc.Signal(name), sun.misc.SignalHandler.SIG_IGN);
            } catch (Throwable e) {
                // not on this platform (Windows has no SIGHUP): the guard then dies with the group
            }
        }
    }

    /** Polls the parent (in case the pipe outlives it); acts as soon as it is gone. */
    private void watchParent(ProcessHandle parent) {
        while (parent != null && parent.isAlive()) {
            try {
                Thread.sleep(PARENT_POLL_MS);
            } catch (InterruptedException e) {
                return;
            }
        }
        act("the sketch's JVM is gone");
    }

    private synchronized void accept(String line) {
        String[] f = line.trim().split(" ");
        try {
            if (f[0].equals("heartbeat") && f.length >= 3) {
                long ms = Long.parseLong(f[1]);
                if (ms < 1 || ms > 10_000) {
                    throw new IllegalArgumentException("stale time out of range");
                }
                staleMillis = ms;
                heartbeat = GuardHeartbeat.open(line.trim().split(" ", 3)[2]);
            } else if (f[0].equals("port") && f.length >= 3) {
                baud = Integer.parseInt(f[1]);
                port = line.trim().split(" ", 3)[2];
                portIdentity = MotorGuardZeroing.identity(port);
                if (heartbeat != null && pauseWatch == null) {
                    pauseWatch = MotorGuardPauseWatch.start(heartbeat, staleMillis, port);
                }
            } else if (f[0].equals("device") && f.length == 4) {
                int id = Integer.parseInt(f[1]);
                int write = Integer.parseInt(f[2]);
                int reply = Integer.parseInt(f[3]);
                if (id < 1 || id > 255 || write < 2 || write > 64 || reply < 1 || reply > 64) {
                    throw new IllegalArgumentException("out of range");
                }
                devices.put(id, new int[] {write, reply});
                if (pauseWatch != null) {
                    pauseWatch.setDevices(zeroMessages(), String.join(", ", devices.keySet().stream()
                            .map(String::valueOf).toArray(String[]::new)));
                }
            } else if (!line.equals(HELLO)) {
                throw new IllegalArgumentException("unknown command");
            }
        } catch (RuntimeException | java.io.IOException e) {
            System.err.println("tactus motor guard: ignored \"" + line + "\" (" + e.getMessage() + ")");
        }
    }

    /** Each device's write with zero torques and zero PWM: [2][id], then zeros. */
    private byte[][] zeroMessages() {
        byte[][] out = new byte[devices.size()][];
        int i = 0;
        for (Map.Entry<Integer, int[]> d : devices.entrySet()) {
            out[i++] = MotorGuardZeroing.zeroMessage(d.getKey(), d.getValue()[0]);
        }
        return out;
    }

    /** Zeroes the motors once, within {@link #ACT_LIMIT_MS}, then ends the process. */
    private synchronized void act(String why) {
        if (acted) {
            return;
        }
        acted = true;
        Thread limit = new Thread(() -> {
            try {
                Thread.sleep(ACT_LIMIT_MS);
            } catch (InterruptedException ignored) {
                // halt anyway
            }
            System.err.println("tactus motor guard: gave up on " + port + " after " + ACT_LIMIT_MS + " ms");
            Runtime.getRuntime().halt(2);
        }, "tactus-motor-guard-limit");
        limit.setDaemon(true);
        limit.start();
        if (pauseWatch != null) {
            pauseWatch.stop();   // the sketch's JVM is gone: the guard opens the port itself from here
        }
        if (port != null && !devices.isEmpty()) {
            System.err.println("tactus motor guard: " + why + "; "
                    + MotorGuardZeroing.zero(port, baud, portIdentity, devices));
            System.err.flush();
        }
        Runtime.getRuntime().halt(0);   // no shutdown hooks to wait for: the job is done
    }
}
