package tactus.soak;

import java.io.PrintStream;
import java.util.Locale;

import ddf.minim.AudioOutput;
import ddf.minim.Minim;
import tactus.PhysicalModel;
import tactus.audio.AudioScheduling;
import tactus.audio.AvatarExchange;
import tactus.audio.ExchangeAvatarLink;
import tactus.audio.LineOut;
import tactus.audio.PhyUGen;
import tactus.audio.SteppedModel;
import tactus.haptics.Board;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.HapticLoop;
import tactus.haptics.HapticSession;
import tactus.haptics.HapticTelemetry;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;
import tactus.scheduling.RealtimeThreads;

/**
 * The soak tool: {@code gradle soak -Pseconds=600 [-Pseed=1]}, or {@code java tactus.soak.Soak SECONDS [SEED]
 * [--buffer=FRAMES] [--skip=CALL_REGEX] [--normal-priority] [--diagnose]} ({@code --skip} leaves out the chaos calls whose name
 * matches, to look past a failure that spoils the rest of a run; {@code --normal-priority} asks no real-time
 * scheduling for the haptic loop and the audio output thread, as before issue 27; {@code --diagnose} adds a
 * {@link StallProbe} that says where the audio thread was when its output stalled). For the given time it runs, on
 * one {@link SoakScene} model:
 *
 * <ul>
 *   <li><b>audio</b>: a {@code PhyUGen} patched into Minim's line out, which plays into Tactus's virtual output
 *       (no sound card needed, paced in real time): Minim's own output thread steps the model, at real-time
 *       priority where the system allows it ({@link AudioScheduling});</li>
 *   <li><b>haptics</b>: a {@code HapticLoop} at 1 kHz in audio mode on the board emulator (the real protocol code,
 *       an in-process link), a scripted hand moving the handle across the string, at the real-time priority a
 *       {@code HapticSession} asks for;</li>
 *   <li><b>draw</b>: a thread at 60 fps reading the snapshot, the energies, the divergence flag and the step
 *       count ({@link Drawer});</li>
 *   <li><b>chaos</b>: a thread making random valid and invalid calls ({@link Chaos}), seeded.</li>
 * </ul>
 *
 * <p>It prints progress every 10 s and, at the end, a summary whose last line is
 * {@code SOAK RESULT escapes=.. hangs=.. nan=.. lateBlocks=.. missedTicks=.. ...}. <b>Failures</b> (exit status 1):
 * exceptions that escaped a thread (uncaught on any thread, including Minim's output thread; out of a reader in
 * draw; of an undocumented type from a call; a haptic loop that stopped itself), hangs (any API call over 1 s, an
 * audio output with no block for 1 s, a model whose step count stands still for 2 s while the audio runs, the model
 * is in realtime stepping and it has not diverged), and NaN reaching an output (audio samples, motor torques). <b>Figures</b>: late audio blocks
 * (the line ran dry), missed haptic ticks, calls made and refused, divergences. Each failure is printed once per
 * kind, with its stack and the defect of issue 15 it most likely is ({@link DefectTags}).
 */
public final class Soak {
    /** A call slower than this is a hang, ns. */
    static final long HANG_NANOS = 1_000_000_000L;
    /** No audio block for this long is a stalled (or dead) output, ns. */
    static final long AUDIO_STALL_NANOS = 1_000_000_000L;
    /** No first audio block after this long is an output that never started, ns. */
    static final long AUDIO_START_NANOS = 3_000_000_000L;
    /** A step count that stands still this long while the audio runs is a stalled model, ns. */
    static final long STEP_STALL_NANOS = 2_000_000_000L;
    /** Progress line period, ns. */
    static final long PROGRESS_NANOS = 10_000_000_000L;
    /** Audio frames per block, by default. */
    static final int DEFAULT_BUFFER = 512;
    /** The longest the shutdown may take before it is called a hang, ms. */
    static final long SHUTDOWN_MILLIS = 10_000;

    private Soak() {
    }

    /** Runs the soak; exits with 0 when nothing escaped, hung or produced NaN, 1 otherwise, 2 on bad arguments. */
    public static void main(String[] args) {
        int status;
        try {
            status = run(args, System.out);
        } catch (IllegalArgumentException e) {
            System.err.println("soak: " + e.getMessage());
            System.err.println("usage: java tactus.soak.Soak SECONDS [SEED] [--buffer=FRAMES] [--skip=CALL_REGEX] "
                    + "[--normal-priority] [--diagnose]");
            status = 2;
        }
        System.out.flush();
        // Runtime.halt, not exit: a thread stuck in a hang must not keep the JVM alive or block a shutdown hook
        Runtime.getRuntime().halt(status);
    }

    /** Runs the soak and returns the exit status (0 or 1). */
    static int run(String[] args, PrintStream out) {
        double seconds = -1;
        long seed = 1;
        int buffer = DEFAULT_BUFFER;
        java.util.regex.Pattern skip = null;
        boolean realtime = true;
        boolean diagnose = false;
        int positional = 0;
        for (String a : args) {
            if (a.equals("--normal-priority")) {
                realtime = false;
            } else if (a.equals("--diagnose")) {
                diagnose = true;
            } else if (a.startsWith("--buffer=")) {
                buffer = Integer.parseInt(a.substring("--buffer=".length()));
            } else if (a.startsWith("--skip=")) {
                skip = java.util.regex.Pattern.compile(a.substring("--skip=".length()));
            } else if (positional == 0) {
                seconds = Double.parseDouble(a);
                positional++;
            } else if (positional == 1) {
                seed = Long.parseLong(a);
                positional++;
            } else {
                throw new IllegalArgumentException("unexpected argument '" + a + "'");
            }
        }
        if (!(seconds > 0) || buffer < 16) {
            throw new IllegalArgumentException("need a duration in seconds > 0 (and --buffer >= 16 frames)");
        }
        return new Run(seconds, seed, buffer, skip, realtime, diagnose, out).go();
    }

    /** One soak run: its parts, the monitor loop and the shutdown. */
    private static final class Run {
        final double seconds;
        final long seed;
        final int buffer;
        final java.util.regex.Pattern skip;
        final boolean realtime;
        final boolean diagnose;
        final PrintStream out;
        final SoakReport report;
        final CallWatch watch;
        volatile boolean audioThreadThrew;

        Run(double seconds, long seed, int buffer, java.util.regex.Pattern skip, boolean realtime, boolean diagnose,
                PrintStream out) {
            this.seconds = seconds;
            this.realtime = realtime;
            this.diagnose = diagnose;
            this.seed = seed;
            this.buffer = buffer;
            this.skip = skip;
            this.out = out;
            this.report = new SoakReport(out);
            this.watch = new CallWatch(HANG_NANOS, report);
        }

        int go() {
            if (skip != null) {
                out.println("soak: leaving out the calls matching '" + skip + "'");
            }
            out.printf(Locale.ROOT, "soak: %.0f s, seed %d; PhyUGen on Minim's line out (virtual output, %d-frame "
                    + "blocks, %d Hz), haptic loop 1 kHz on the board emulator, draw at 60 fps, chaos calls%n",
                    seconds, seed, buffer, SoakScene.RATE);
            if (!realtime) {
                out.println("soak: no real-time scheduling asked for the haptic loop and the audio output thread");
                AudioScheduling.setRealtimePriority(0);
            }
            // Tactus's virtual output even where a sound card exists: the soak is silent and the same everywhere.
            System.setProperty("javax.sound.sampled.SourceDataLine", "tactus.audio.VirtualMixerProvider");
            AudioWatch audioWatch = new AudioWatch(report, buffer, SoakScene.RATE);
            Thread.setDefaultUncaughtExceptionHandler((t, e) -> {
                boolean minim = t == audioWatch.audioThread() || isMinimOutput(e);
                if (minim) {
                    audioThreadThrew = true;
                }
                report.escape("uncaught on " + (minim ? "Minim's output thread '" : "thread '") + t.getName() + "'", e);
            });

            PhysicalModel m = SoakScene.create();
            PhyUGen ugen = new PhyUGen(m);
            ugen.listenToMass(SoakScene.mass(SoakScene.LISTENED), SteppedModel.Y, 30, 0);
            AvatarExchange exchange = new AvatarExchange(AvatarExchange.ForceMode.AVERAGE);
            ugen.attachAvatar(SoakScene.PLECTRUM, exchange);

            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
            emulator.setHand(Hand.scripted(SoakScene::handAt));
            Board board = new Board(emulator.connect());
            Device device = new Device((byte) 5, board);
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            TorqueWatch link = new TorqueWatch(new ExchangeAvatarLink(exchange), report);
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), link);
            loop.setRate(1000);
            loop.setRealtimePriority(realtime ? HapticSession.REALTIME_PRIORITY : 0);
            loop.setMode(HapticLoop.Mode.AUDIO);
            loop.setPositionGain(SoakScene.ALPHA);
            loop.setForceGain(SoakScene.BETA);
            loop.setMirrorX(true);
            loop.setOrigin(SoakScene.originX(), SoakScene.originY(), 0);
            link.watch(loop);

            Minim minim = new Minim(new SketchFiles());
            AudioOutput audio = LineOut.open(minim, Minim.STEREO, buffer, SoakScene.RATE, out);
            Drawer drawer = new Drawer(m, report, watch);
            Chaos chaos = new Chaos(m, ugen, exchange, report, watch, seed, skip);
            Thread drawThread = new Thread(drawer, "soak-draw");
            Thread chaosThread = new Thread(chaos, "soak-chaos");
            drawThread.setDaemon(true);
            chaosThread.setDaemon(true);

            StallProbe probe = diagnose ? new StallProbe(audioWatch) : null;
            if (probe != null) {
                Thread p = new Thread(probe, "soak-stall-probe");
                p.setDaemon(true);
                p.start();
            }
            long start = System.nanoTime();
            audio.addListener(audioWatch);
            ugen.patch(audio);
            loop.start();
            drawThread.start();
            chaosThread.start();
            monitor(start, audioWatch, drawer, loop, emulator);

            chaos.stop();
            drawer.stop();
            join(chaosThread);
            join(drawThread);
            shutdown(loop, audio, minim, emulator);
            double elapsed = (System.nanoTime() - start) * 1e-9;
            HapticTelemetry tel = loop.telemetry();
            report.missedHapticTicks = tel.missedSteps;
            report.hapticTelemetry = tel.toString() + ", " + loop.scheduling();
            report.audioScheduling = AudioScheduling.status();
            report.realtimeThreads = realtimeThreads();
            if (drawer.steps >= 0) {
                report.modelSteps = drawer.steps;
            }
            String stuck = watch.stuck();
            if (!stuck.isEmpty()) {
                out.print(stuck);
            }
            if (probe != null) {
                probe.stop();
                out.print(probe.summary());
            }
            out.println(report.summary(elapsed, seed));
            out.flush();
            return report.failed() ? 1 : 0;
        }

        private void monitor(long start, AudioWatch aw, Drawer drawer, HapticLoop loop, BoardEmulator emulator) {
            long end = start + (long) (seconds * 1e9);
            long nextProgress = start + PROGRESS_NANOS;
            boolean audioStallReported = false;
            boolean stepStallReported = false;
            boolean hapticFailureReported = false;
            boolean emulatorNanReported = false;
            long lastSteps = Long.MIN_VALUE;
            long lastStepChange = start;
            while (System.nanoTime() < end) {
                try {
                    Thread.sleep(10);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return;
                }
                long now = System.nanoTime();
                watch.check();

                // ---- the audio output: still delivering blocks?
                long last = aw.lastBlockNanos();
                Thread at = aw.audioThread();
                boolean audioFlows = last != 0 && now - last < AUDIO_STALL_NANOS / 5;
                if (last == 0 && now - start > AUDIO_START_NANOS && !audioStallReported) {
                    audioStallReported = true;
                    if (audioThreadThrew) {
                        out.println("soak: the audio output never delivered a block: Minim's output thread died of "
                                + "the escape above");
                    } else {
                        report.hang("Minim's output thread", String.format(Locale.ROOT,
                                "audio output stalled: no block in the first %.0f s", AUDIO_START_NANOS * 1e-9), null);
                    }
                }
                if (last != 0 && now - last > AUDIO_STALL_NANOS) {
                    if (!audioStallReported) {
                        audioStallReported = true;
                        if (at != null && !at.isAlive()) {
                            if (audioThreadThrew) {
                                out.println("soak: audio output stopped: Minim's output thread died of the escape above");
                            } else {
                                report.escape("Minim's output thread", new IllegalStateException(
                                        "audio output stopped: Minim's output thread died without an uncaught exception"));
                            }
                        } else {
                            report.hang("Minim's output thread", String.format(Locale.ROOT,
                                    "audio output stalled: no block for %.1f s", (now - last) * 1e-9),
                                    at == null ? null : at.getStackTrace());
                        }
                    }
                } else if (last != 0) {
                    audioStallReported = false;
                }

                // ---- the model: still stepping while the audio runs and owns it (unless it diverged and is frozen)?
                long steps = drawer.steps;
                boolean fresh = now - drawer.readAt < AUDIO_STALL_NANOS / 5;
                if (steps != lastSteps || drawer.diverged || !drawer.realtime || !audioFlows || !fresh) {
                    if (steps != lastSteps) {
                        stepStallReported = false;
                    }
                    lastSteps = steps;
                    lastStepChange = now;
                } else if (now - lastStepChange > STEP_STALL_NANOS && !stepStallReported) {
                    stepStallReported = true;
                    report.hang("model", String.format(Locale.ROOT, "stepping stalled: the step count stayed at %d "
                            + "for %.1f s while the audio output ran and the model was not diverged", steps,
                            (now - lastStepChange) * 1e-9), at == null ? null : at.getStackTrace());
                }

                // ---- haptics
                String failure = loop.failure();
                if (failure != null && !hapticFailureReported) {
                    hapticFailureReported = true;
                    report.escape("haptic loop", new IllegalStateException("the haptic loop stopped: " + failure));
                }
                double t1 = emulator.motorTorque(1);
                double t2 = emulator.motorTorque(2);
                if ((!Double.isFinite(t1) || !Double.isFinite(t2)) && !emulatorNanReported) {
                    emulatorNanReported = true;
                    report.nan("board emulator", "motor torques " + t1 + ", " + t2 + " N m");
                }

                if (now >= nextProgress) {
                    nextProgress += PROGRESS_NANOS;
                    if (steps >= 0) {
                        report.modelSteps = steps;
                    }
                    report.missedHapticTicks = loop.telemetry().missedSteps;
                    out.println(report.progress((now - start) * 1e-9));
                    out.flush();
                }
            }
        }

        /** @return the CPU time a thread of this process has used so far (user + system), s; -1 if unknown. */
        static double cpuSeconds(String tid) {
            try {
                String s = new String(java.nio.file.Files.readAllBytes(java.nio.file.Paths.get("/proc/self/task", tid,
                        "stat")), java.nio.charset.StandardCharsets.UTF_8);
                String[] f = s.substring(s.lastIndexOf(')') + 2).split(" ");
                return (Long.parseLong(f[11]) + Long.parseLong(f[12])) / 100.0;   // clock ticks of 10 ms
            } catch (java.io.IOException | RuntimeException e) {
                return -1;
            }
        }

        /** @return the JVM's real-time threads now, as "name priority" (Linux only; empty elsewhere). */
        private static String realtimeThreads() {
            java.util.Map<String, java.util.List<Integer>> byName = new java.util.TreeMap<>();
            for (String tid : RealtimeThreads.threadsNamed(java.util.regex.Pattern.compile(".*"))) {
                int[] p = RealtimeThreads.policyOf(tid);
                if (p != null && p[0] != 0) {
                    String name = threadName(tid);
                    byName.computeIfAbsent(name.replaceAll("\\d+$", "#"), k -> new java.util.ArrayList<>()).add(p[1]);
                    if (!name.contains("Thread#") && !name.contains("Compiler")) {
                        byName.computeIfAbsent(name + " CPU s", k -> new java.util.ArrayList<>())
                                .add((int) Math.round(cpuSeconds(tid)));
                    }
                }
            }
            return byName.isEmpty() ? "none" : byName.toString();
        }

        private static String threadName(String tid) {
            try {
                return new String(java.nio.file.Files.readAllBytes(java.nio.file.Paths.get("/proc/self/task", tid,
                        "comm")), java.nio.charset.StandardCharsets.UTF_8).trim();
            } catch (java.io.IOException e) {
                return "?";
            }
        }

        /** @return true when the exception went through Minim's output loop (its thread died of it). */
        private static boolean isMinimOutput(Throwable e) {
            for (StackTraceElement f : e.getStackTrace()) {
                if (f.getClassName().startsWith("ddf.minim.javasound.JSAudioOutput")) {
                    return true;
                }
            }
            return false;
        }

        private static void join(Thread t) {
            try {
                t.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }

        /** Closes everything on a helper thread, so that a close that hangs is reported instead of hanging. */
        private void shutdown(HapticLoop loop, AudioOutput audio, Minim minim, BoardEmulator emulator) {
            Thread closer = new Thread(() -> {
                loop.close();
                audio.close();
                minim.stop();
                emulator.close();
            }, "soak-shutdown");
            closer.setDaemon(true);
            closer.start();
            try {
                closer.join(SHUTDOWN_MILLIS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            if (closer.isAlive()) {
                report.hang("shutdown", "closing the haptic loop, the audio output and Minim took over "
                        + SHUTDOWN_MILLIS / 1000 + " s", closer.getStackTrace());
            }
        }
    }
}
