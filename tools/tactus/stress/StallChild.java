package tactus.stress;

import java.util.Locale;
import java.util.concurrent.locks.LockSupport;
import tactus.PhysicalModel;
import tactus.haptics.AvatarLink;
import tactus.hapticstability.ForwardingAvatarLink;
import tactus.haptics.HaplyPreset;
import tactus.haptics.HapticLoop;
import tactus.haptics.HapticSession;
import tactus.haptics.PhysicalModelAvatar;

/**
 * One run of {@link HapticStallStress}, in a JVM of its own: an emulated Haply session as a sketch opens it
 * (real-time request, 1 kHz, haptics-only, a free avatar), with a thread that reads the avatar's position every 2 ms
 * and moves the emulated hand every half second (as HapticSessionTest, where the stall was seen, and a sketch's
 * {@code draw()} do), optionally beside a thread that makes garbage at a set
 * rate (as a busy {@code draw()} does) and a thread that reads the loop's telemetry every few milliseconds. It
 * records the start of every tick and the collector's pauses, and prints one line:
 *
 * <pre>RESULT ticks=N worstLateMs=X over20=N gcPauses=N gcMaxMs=X lateMs=X lateInGcMs=X lateInSafepointsMs=X
 *        failure=... sched=...</pre>
 *
 * where a tick's lateness is its start minus its deadline (start of the first tick + k periods), the sum of
 * lateness above one period is {@code lateMs}, and {@code lateInGcMs} and {@code lateInSafepointsMs} are the parts
 * of it that fall inside a collector's safepoint and inside any safepoint, read from the JVM's own safepoint log
 * ({@code -Xlog:safepoint:file=F:timenanos}, whose time stamps are {@code System.nanoTime()}). Arguments:
 * seconds, garbage MB/s, telemetry read period in ms (0: none), the safepoint log's path (optional). With
 * {@code -Dtactus.stress.audio=true} the model is the paper's plucked string stepped by a {@code PhyUGen} at
 * 44.1 kHz and the loop runs in AUDIO mode, as in the audio-haptic examples; {@code -Dtactus.stress.reader=false}
 * leaves the reader thread out; {@code -Dtactus.stress.heapWarmup=false} turns the loop's heap warm-up off;
 * {@code -Dtactus.stress.warmupMB=N} makes N MB of garbage before the loop starts;
 * {@code -Dtactus.stress.deadline=false} keeps the loop at SCHED_FIFO instead of
 * SCHED_DEADLINE; {@code -Dtactus.stress.rtSpinners=true} adds one SCHED_FIFO 1 process per CPU that keeps its
 * core busy for the rest of the run (as a long compilation does with the compilers at real-time priority), so that the
 * kernel's fair server must step in; {@code -Dtactus.stress.verbose=true} prints every tick more than 2 ms late and
 * where the loop thread was when no tick started for 8 ms.
 */
public final class StallChild {
    private static volatile Object sink;
    /** With -Dtactus.stress.verbose=true, every tick more than 2 ms late is printed with its time. */
    private static final boolean VERBOSE = Boolean.getBoolean("tactus.stress.verbose");

    private StallChild() {
    }

    /** Records the start of each tick: the loop calls {@code setTarget} once per tick, first thing after the read. */
    private static final class TimedAvatar extends ForwardingAvatarLink {
        final long[] starts;
        final long[] modelDone;
        volatile int n;

        TimedAvatar(AvatarLink inner, int capacity) {
            super(inner);
            this.starts = new long[capacity];
            this.modelDone = new long[capacity];
        }

        @Override
        public void setTarget(double x, double y, double z) {
            int i = n;
            if (i < starts.length) {
                starts[i] = System.nanoTime();
                n = i + 1;
            }
            inner.setTarget(x, y, z);
        }

        @Override
        public long takeForceCounted(double[] out) {
            long steps = inner.takeForceCounted(out);
            int i = n - 1;
            if (i >= 0 && i < modelDone.length) {
                modelDone[i] = System.nanoTime();
            }
            return steps;
        }
    }

    /**
     * Runs one session and prints its RESULT line.
     *
     * @param args seconds, garbage MB/s, telemetry read period in ms
     * @throws Exception if the session cannot be opened
     */
    public static void main(String[] args) throws Exception {
        double seconds = args.length > 0 ? Double.parseDouble(args[0]) : 2;
        long garbageMBs = args.length > 1 ? Long.parseLong(args[1]) : 0;
        int telemetryMs = args.length > 2 ? Integer.parseInt(args[2]) : 0;
        String safepointLog = args.length > 3 ? args[3] : null;
        boolean audio = Boolean.getBoolean("tactus.stress.audio");
        long stealAtStart = stealJiffies();
        HapticSession session = HapticSession.openEmulated(null, HaplyPreset.HAPLY_2018);
        PhysicalModel pm;
        TimedAvatar avatar;
        int capacity = (int) (seconds * 1000 * 1.5) + 1000;
        if (audio) {
            // the audio-haptic examples' way: the paper's plucked string stepped by a PhyUGen at 44.1 kHz (paced in
            // real time by a silent output, 256-frame buffers), the loop in AUDIO mode through an exchange
            pm = tactus.demo.PluckScene.build(session.home());
            tactus.audio.PhyUGen ugen = new tactus.audio.PhyUGen(pm);
            ugen.listenToMass(tactus.demo.PluckScene.mass(tactus.demo.PluckScene.LISTENED_MASS),
                    tactus.audio.SteppedModel.Y, 30, 0);
            tactus.audio.AvatarExchange exchange = new tactus.audio.AvatarExchange(
                    tactus.audio.AvatarExchange.ForceMode.AVERAGE);
            ugen.attachAvatar(tactus.demo.PluckScene.PLECTRUM, exchange);
            ugen.patch(new ddf.minim.AudioOutput(new tactus.audio.SilentAudioOut(1, 256,
                    tactus.demo.PluckScene.AUDIO_RATE)));
            avatar = new TimedAvatar(new tactus.audio.ExchangeAvatarLink(exchange), capacity);
        } else {
            pm = new PhysicalModel(1000);
            pm.addHapticInput3D("avatar", session.home(), 5);
            pm.init();
            avatar = new TimedAvatar(new PhysicalModelAvatar(pm, "avatar"), capacity);
        }
        String avatarName = audio ? tactus.demo.PluckScene.PLECTRUM : "avatar";
        HapticLoop loop = session.attach(avatar);
        if (audio) {
            loop.setMode(HapticLoop.Mode.AUDIO);
        }
        long warmupMB = Long.getLong("tactus.stress.warmupMB", 0);
        for (long b = 0; b < warmupMB << 20; b += 1024) {
            sink = new byte[1024];   // the collections that this garbage causes happen before the loop starts
        }
        if ("false".equals(System.getProperty("tactus.stress.heapWarmup"))) {
            loop.setHeapWarmup(false);
        }
        if ("false".equals(System.getProperty("tactus.stress.deadline"))) {
            loop.setDeadlineScheduling(false);
        }
        loop.start();
        if (Boolean.getBoolean("tactus.stress.rtSpinners")) {
            // once the loop runs at its policy: before, its own chrt call would be starved too
            long waitUntil = System.nanoTime() + 10_000_000_000L;
            while (loop.ticks() < 200 && loop.isRunning() && System.nanoTime() < waitUntil) {
                Thread.sleep(5);
            }
            startRealtimeSpinners(seconds);
        }
        if (VERBOSE) {
            startDiagnoser(loop, avatar);
        }
        // the sketch's side, as HapticSessionTest (where the stall was seen) and a draw() do it: move the hand
        // towards a pixel now and then, and read the avatar's position every 2 ms
        startDaemon("reader", () -> {
            if ("false".equals(System.getProperty("tactus.stress.reader"))) {
                return;
            }
            double[] ws = new double[4];
            session.workspace(ws);
            for (int k = 0; ; k++) {
                if (k % 250 == 0) {
                    double u = (k / 250) % 2 == 0 ? 0.3 : 0.7;
                    session.handTowardsPixel(ws[0] + u * (ws[1] - ws[0]), ws[2] + u * (ws[3] - ws[2]));
                }
                sink = pm.getMatPosition(avatarName);
                LockSupport.parkNanos(2_000_000L);
            }
        });
        if (garbageMBs > 0) {
            startDaemon("garbage", () -> {
                long perMs = garbageMBs * 1000;
                while (true) {
                    for (long b = 0; b < perMs; b += 1024) {
                        sink = new byte[1024];
                    }
                    LockSupport.parkNanos(1_000_000);
                }
            });
        }
        if (telemetryMs > 0) {
            startDaemon("telemetry-reader", () -> {
                while (true) {
                    sink = loop.telemetry();
                    LockSupport.parkNanos(telemetryMs * 1_000_000L);
                }
            });
        }
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (System.nanoTime() < end && loop.isRunning()) {
            Thread.sleep(10);
        }
        long stoppedAt = System.nanoTime();
        int n = avatar.n;
        loop.stop();
        long period = 1_000_000L;
        double worst = 0;
        double lateSum = 0;
        double lateInGc = 0;
        double lateInSafepoints = 0;
        int over20 = 0;
        Pauses pauses = Pauses.read(safepointLog);
        // lateness against the loop's own schedule: each tick is due one period after the previous one's
        // deadline, and a tick later than a period restarts the schedule (as HapticLoop does)
        long due = n > 0 ? avatar.starts[0] : 0;
        for (int i = 1; i < n; i++) {
            due += period;
            long late = avatar.starts[i] - due;
            if (late > period) {
                due = avatar.starts[i];
            }
            double lateMs = late / 1e6;
            if (VERBOSE && lateMs > 2) {
                long at = System.currentTimeMillis() - (System.nanoTime() - avatar.starts[i]) / 1_000_000L;
                System.out.printf(Locale.ROOT, "late tick %d at %.3f: %.3f ms, the tick before spent %.3f ms in the "
                                + "model, %.3f ms of it in safepoints (%.3f ms reaching them)%n", i, at / 1e3, lateMs,
                        (avatar.modelDone[i - 1] - avatar.starts[i - 1]) / 1e6,
                        pauses.overlapMs(avatar.starts[i] - late, avatar.starts[i], false),
                        pauses.reachingMs(avatar.starts[i] - late, avatar.starts[i]));
            }
            worst = Math.max(worst, lateMs);
            if (lateMs > 20) {
                over20++;
            }
            if (late > period) {
                lateSum += lateMs;
                lateInGc += pauses.overlapMs(avatar.starts[i] - late, avatar.starts[i], true);
                lateInSafepoints += pauses.overlapMs(avatar.starts[i] - late, avatar.starts[i], false);
            }
        }
        if (n > 0) {
            // a loop that stopped ticking before the end: the tick it owes is late by the time since it was due
            worst = Math.max(worst, (stoppedAt - avatar.starts[n - 1] - period) / 1e6);
            if (VERBOSE && (stoppedAt - avatar.starts[n - 1] - period) / 1e6 > 2) {
                System.out.printf(Locale.ROOT, "late tick %d (owed at the end): %.3f ms, %.3f ms of it in safepoints%n",
                        n, (stoppedAt - avatar.starts[n - 1] - period) / 1e6,
                        pauses.overlapMs(avatar.starts[n - 1] + period, stoppedAt, false));
            }
            if ((stoppedAt - avatar.starts[n - 1] - period) / 1e6 > 20) {
                over20++;
            }
        }
        System.out.printf(Locale.ROOT, "RESULT ticks=%d worstLateMs=%.3f over20=%d gcPauses=%d gcMaxMs=%.0f "
                        + "lateMs=%.3f lateInGcMs=%.3f lateInSafepointsMs=%.3f stealMs=%d failure=%s sched=%s%n", n, worst, over20,
                pauses.gcCount(), pauses.gcMaxMs(), lateSum, lateInGc, lateInSafepoints,
                (stealJiffies() - stealAtStart) * 10,
                n < 2 ? "the loop ticked " + n + " times in " + seconds + " s" : loop.failure(),
                loop.scheduling());
        System.out.flush();
        session.close();
        Runtime.getRuntime().halt(0);
    }

    /**
     * Verbose runs only: a thread at a real-time priority above the loop's that looks every millisecond, and when
     * no tick has started for 8 ms, prints where the loop thread is (its Java stack and what Linux says of it).
     */
    /**
     * One process per CPU, each pinned to its CPU and at SCHED_FIFO 1, that keeps its core busy until about
     * {@code seconds} have passed: what a long compilation does with the JIT compilers at real-time priority (a
     * native thread, never in the way of a safepoint). Normal threads (the hog, the reader) then get a core only
     * through the kernel's fair server, 50 ms a second, which stops every SCHED_FIFO thread on that CPU while it
     * runs. The spinners end themselves: a shell that would kill them runs at normal priority and would wait.
     */
    private static void startRealtimeSpinners(double seconds) throws java.io.IOException {
        int cpus = Runtime.getRuntime().availableProcessors();
        String spin = "end=$(( $(date +%s) + " + (long) Math.ceil(seconds) + " )); while [ $(date +%s) -lt $end ]; do "
                + "i=0; while [ $i -lt 20000 ]; do i=$((i+1)); done; done";
        for (int c = 0; c < cpus; c++) {
            new ProcessBuilder("taskset", "-c", Integer.toString(c), "chrt", "-f", "1", "sh", "-c", spin)
                    .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.INHERIT).start();
        }
    }

    /**
     * The time the hypervisor gave this virtual machine's CPUs to others ("steal", the eighth number of
     * /proc/stat's cpu line), in jiffies of 10 ms; 0 where it cannot be read.
     */
    private static long stealJiffies() {
        try {
            String[] f = java.nio.file.Files.readAllLines(java.nio.file.Paths.get("/proc/stat")).get(0).trim()
                    .split("\\s+");
            return f.length > 8 ? Long.parseLong(f[8]) : 0;
        } catch (java.io.IOException | RuntimeException e) {
            return 0;
        }
    }

    private static void startDiagnoser(HapticLoop loop, TimedAvatar avatar) {
        startDaemon("stall-diagnoser", () -> {
            try {
                String me = java.nio.file.Files.readSymbolicLink(java.nio.file.Paths.get("/proc/thread-self"))
                        .getFileName().toString();
                new ProcessBuilder("chrt", "-f", "-p", "60", me).start().waitFor();
                Thread loopThread = null;
                while (loopThread == null) {
                    for (Thread t : Thread.getAllStackTraces().keySet()) {
                        if (t.getName().equals("tactus-haptic-loop")) {
                            loopThread = t;
                        }
                    }
                    LockSupport.parkNanos(1_000_000);
                }
                int lastN = avatar.n;
                long lastChange = System.nanoTime();
                boolean reported = false;
                while (true) {
                    LockSupport.parkNanos(1_000_000);
                    int n = avatar.n;
                    long now = System.nanoTime();
                    if (n != lastN) {
                        lastN = n;
                        lastChange = now;
                        reported = false;
                    } else if (!reported && now - lastChange > 8_000_000L) {
                        reported = true;
                        StringBuilder b = new StringBuilder("stalled tick " + n + ": " + linuxState() + " | java:");
                        for (StackTraceElement e : loopThread.getStackTrace()) {
                            b.append(" <- ").append(e);
                            if (b.length() > 1500) {
                                break;
                            }
                        }
                        b.append(" | after ").append((System.nanoTime() - lastChange) / 1_000_000).append(" ms");
                        System.out.println(b);
                    }
                }
            } catch (Exception e) {
                System.out.println("stall-diagnoser: " + e);
            }
        });
    }

    private static String linuxState() {
        StringBuilder b = new StringBuilder();
        java.io.File[] tasks = new java.io.File("/proc/self/task").listFiles();
        for (java.io.File t : tasks == null ? new java.io.File[0] : tasks) {
            try {
                String comm = new String(java.nio.file.Files.readAllBytes(new java.io.File(t, "comm").toPath())).trim();
                String stat = new String(java.nio.file.Files.readAllBytes(new java.io.File(t, "stat").toPath()));
                String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
                if (comm.startsWith("tactus-haptic-l") || f[0].equals("R") || f[0].equals("D")) {
                    b.append(comm).append(' ').append(f[0]).append(" cpu").append(f[36]).append(" wchan ")
                            .append(new String(java.nio.file.Files.readAllBytes(new java.io.File(t, "wchan")
                                    .toPath())).trim()).append("; ");
                }
            } catch (Exception e) {
                // gone
            }
        }
        return b.toString();
    }

    private static void startDaemon(String name, Runnable body) {
        Thread t = new Thread(body, name);
        t.setDaemon(true);
        t.start();
    }
}
