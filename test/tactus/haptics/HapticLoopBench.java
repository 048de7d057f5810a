package tactus.haptics;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.Locale;
import java.util.concurrent.locks.LockSupport;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;
import tactus.haptics.emulator.PtyPair;
import tactus.haptics.transport.SerialTransport;

/**
 * Measures the haptic loop's telemetry (not a test; run on demand):
 * {@code java ... tactus.haptics.HapticLoopBench SECONDS MODE [rt[=PRIORITY]] [inproc]}.
 *
 * <p>MODE "haptics": the paper's HeavyMassChain stepped by the haptic thread at 1 kHz. "audio": a 200-mass
 * string at 44.1 kHz stepped by an audio-like thread in bursts of 1024 steps per 23.2 ms (what Minim's
 * callback does with its default buffer), the loop in {@link HapticLoop.Mode#AUDIO} with its default
 * decoupled avatar. "audio-locked": the same, the loop calling the model directly (through its lock).
 * "audio-decoupled" is an old name for "audio".
 *
 * <p>"rt" asks for real-time scheduling of the loop thread ({@link HapticLoop#setRealtimePriority(int)},
 * priority 50 unless given). "inproc" uses the in-process emulator instead of the default socat pty pair
 * with the emulator on its own thread (the real serial code path).
 *
 * <p>Prints the telemetry, the board counters, the audio thread's own timing, the load average before and
 * after, and one row for the table of {@code docs/haptics.md}.
 */
public final class HapticLoopBench {
    private HapticLoopBench() {
    }

    public static void main(String[] args) throws Exception {
        double seconds = args.length > 0 ? Double.parseDouble(args[0]) : 60;
        String mode = args.length > 1 ? args[1] : "haptics";
        int rt = 0;
        boolean inproc = false;
        for (int i = 2; i < args.length; i++) {
            if (args[i].startsWith("rt")) {
                rt = args[i].startsWith("rt=") ? Integer.parseInt(args[i].substring(3)) : 50;
            } else if (args[i].equals("inproc")) {
                inproc = true;
            } else {
                throw new IllegalArgumentException("unknown option " + args[i]);
            }
        }
        boolean audio = mode.startsWith("audio");
        boolean locked = mode.equals("audio-locked");
        String loadBefore = loadAverage();
        try (PtyPair pty = inproc ? null : PtyPair.open()) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
            emulator.setHand(Hand.scripted((t, out) -> {
                out[0] = 0.02 * Math.sin(2 * Math.PI * 0.5 * t);
                out[1] = 0.08 + 0.01 * Math.sin(2 * Math.PI * 0.3 * t);
            }));
            Board board;
            if (inproc) {
                board = new Board(emulator.connect());
            } else {
                emulator.serve(SerialTransport.open(pty.boardEnd(), 0));
                board = new Board(pty.hostEnd(), 0);
            }
            Device device = new Device((byte) 5, board);
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            PhysicalModel pm = audio ? string() : chain();
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(),
                    new PhysicalModelAvatar(pm, "hapticMass"));
            loop.setOrigin(0, -200 * 0.08, 0);
            loop.setRealtimePriority(rt);
            AudioLike audioThread = null;
            if (audio) {
                loop.setMode(HapticLoop.Mode.AUDIO);
                loop.setDecoupledInAudioMode(!locked);
                loop.setForceGain(1);
                audioThread = new AudioLike(pm);
                audioThread.start();
            }
            loop.start();
            Thread.sleep((long) (seconds * 1000));
            HapticTelemetry t = loop.telemetry();
            String scheduling = loop.scheduling();
            String cpu = threadCpu(t.seconds);
            if (audioThread != null) {
                audioThread.halt();
            }
            loop.close();
            String loadAfter = loadAverage();
            System.out.println(mode + " " + t + ", " + scheduling);
            System.out.println("board: frames " + board.framesRead() + ", skipped " + board.framesSkipped()
                    + ", id mismatches " + board.idMismatches() + ", emulator writes " + emulator.writes()
                    + ", late bytes " + emulator.lateBytes());
            if (audioThread != null) {
                System.out.println(audioThread.report());
            }
            System.out.println("CPU per thread (% of one core): " + cpu);
            System.out.println("load average (1 min): " + loadBefore + " -> " + loadAfter);
            System.out.println(String.format(Locale.ROOT,
                    "| %s%s%s, %.0f s | %s → %s | %.1f Hz | %,d of %,d (%.3f %%) | %.0f µs / %.0f µs / %.1f ms "
                            + "| %.0f µs / %.0f µs / %.1f ms | %,d |",
                    mode, rt > 0 ? (scheduling.startsWith("real-time") ? " rt" : " rt refused") : "",
                    inproc ? " in-process" : "", seconds, loadBefore, loadAfter, t.achievedHz, t.missedSteps,
                    t.ticks, 100 * t.missedFraction(), t.jitterP50Us, t.jitterP99Us, t.jitterMaxUs / 1000,
                    t.computeP50Us, t.computeP99Us, t.computeMaxUs / 1000, t.staleTicks));
            emulator.close();
        }
    }

    /** CPU time of the loop's, the emulator's and the audio threads, as a percentage of one core. */
    private static String threadCpu(double seconds) {
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        StringBuilder sb = new StringBuilder();
        for (Thread th : Thread.getAllStackTraces().keySet()) {
            String n = th.getName();
            if (n.startsWith("tactus-") || n.equals("audio-like")) {
                long ns = mx.getThreadCpuTime(th.getId());
                if (ns >= 0) {
                    sb.append(sb.length() == 0 ? "" : ", ").append(n).append(' ')
                            .append(String.format(Locale.ROOT, "%.1f", 100 * ns / 1e9 / seconds));
                }
            }
        }
        return sb.toString();
    }

    private static String loadAverage() {
        try {
            return new String(Files.readAllBytes(Paths.get("/proc/loadavg")), StandardCharsets.US_ASCII)
                    .split(" ")[0];
        } catch (IOException e) {
            return "?";
        }
    }

    /** An audio-like thread: 1024 model steps every 1024 / 44100 s on absolute deadlines, as Minim's callback. */
    private static final class AudioLike extends Thread {
        private final PhysicalModel pm;
        private volatile boolean stop;
        private long bursts;
        private long busyNanos;
        private long worstBurst;
        private long lateBursts;   // bursts that ended after their buffer's deadline (an audible dropout)

        AudioLike(PhysicalModel pm) {
            super("audio-like");
            this.pm = pm;
            setDaemon(true);
        }

        @Override
        public void run() {
            long period = Math.round(1024 / 44100.0 * 1e9);
            long next = System.nanoTime();   // start of the current buffer; it is due one period later
            while (!stop) {
                long b0 = System.nanoTime();
                pm.computeNSteps(1024);
                long b1 = System.nanoTime();
                bursts++;
                busyNanos += b1 - b0;
                worstBurst = Math.max(worstBurst, b1 - b0);
                if (b1 - next > period) {
                    lateBursts++;
                }
                next += period;
                long wait = next - System.nanoTime();
                if (wait > 0) {
                    LockSupport.parkNanos(wait);
                } else {
                    next = System.nanoTime() + period;
                }
            }
        }

        void halt() throws InterruptedException {
            stop = true;
            join(2000);
        }

        String report() {
            return String.format(Locale.ROOT, "audio-like thread: %d bursts of 1024 steps, mean %.0f us, max %.0f us, "
                    + "%d ended after their deadline", bursts, busyNanos / 1e3 / Math.max(1, bursts), worstBurst / 1e3,
                    lateBursts);
        }
    }

    static PhysicalModel chain() {
        PhysicalModel pm = new PhysicalModel(1000);
        pm.addHapticInput3D("hapticMass", new Vect3D(), 10);
        for (int i = 0; i < 10; i++) {
            pm.addMass3D("m" + i, 50, new Vect3D(0.1 * (i + 1), 0, 0), new Vect3D());
        }
        for (int i = 0; i < 9; i++) {
            pm.addSpringDamper3D("k" + i, 0.1, 0.003, 0.05, "m" + i, "m" + (i + 1));
        }
        pm.addSpringDamper3D("grip", 0.1, 0.003, 0.05, "hapticMass", "m0");
        pm.init();
        return pm;
    }

    static PhysicalModel string() {
        PhysicalModel pm = new PhysicalModel(44100);
        pm.addHapticInput3D("hapticMass", new Vect3D(0, 1, 0), 30);
        pm.addGround3D("g0", new Vect3D(-1, 0, 0));
        pm.addGround3D("g1", new Vect3D(1, 0, 0));
        int n = 200;
        for (int i = 0; i < n; i++) {
            pm.addMass3D("s" + i, 1, new Vect3D(-1 + 2.0 * (i + 1) / (n + 1), 0, 0), new Vect3D());
        }
        pm.addSpringDamper3D("e0", 0, 0.1, 0.001, "g0", "s0");
        for (int i = 0; i + 1 < n; i++) {
            pm.addSpringDamper3D("e" + (i + 1), 0, 0.1, 0.001, "s" + i, "s" + (i + 1));
        }
        pm.addSpringDamper3D("e" + n, 0, 0.1, 0.001, "s" + (n - 1), "g1");
        pm.addSpringDamper3D("pluck", 0.5, 0.01, 0.001, "hapticMass", "s" + (n / 2));
        pm.init();
        return pm;
    }
}
