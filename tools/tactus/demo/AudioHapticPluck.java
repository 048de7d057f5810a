package tactus.demo;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import ddf.minim.AudioOutput;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.audio.AvatarExchange;
import tactus.audio.PhyUGen;
import tactus.audio.SilentAudioOut;
import tactus.audio.SteppedModel;
import tactus.audio.WavWriter;
import tactus.haptics.Board;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.HapticLoop;
import tactus.haptics.HapticSession;
import tactus.haptics.TimingVerdict;
import tactus.haptics.HapticTelemetry;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;
import tactus.report.LineChart;

/**
 * The audio-haptic plucked string of the paper, end to end and headless, as {@code gradle demo} runs it.
 *
 * <ul>
 *   <li><b>Device</b>: an emulated 2018 Haply ({@link BoardEmulator}, M0 firmware) reached through the real
 *       protocol code ({@link Board}, {@link Device}, the wire format) over an in-process link; a scripted,
 *       rigid hand moves its handle along {@link PluckPath}.</li>
 *   <li><b>Haptics</b>: a {@link HapticLoop} at 1 kHz in {@code Mode.AUDIO}: each tick it reads the encoders,
 *       runs the pantograph kinematics, maps the handle into the model ({@link DeviceMapping}), hands the
 *       position to the audio thread and takes back the force on the plectrum through an
 *       {@link AvatarExchange} (lock-free), and writes the torques J<sup>T</sup>F.</li>
 *   <li><b>Audio</b>: a {@link PhyUGen} steps the model ({@link PluckScene}) once per sample at 44.1 kHz,
 *       listening to a mass near one end, patched into a Minim {@code AudioOutput} over a
 *       {@link SilentAudioOut} (256-frame buffers, computed at the pace of the sample rate, as a sound card
 *       would ask for them); a listener keeps the samples, which become {@code pluck.wav}.</li>
 * </ul>
 *
 * <p>Everything runs in real time: the run lasts {@value PluckPath#DURATION} s. Afterwards the fundamental
 * and the next partials are measured by FFT on the free ringing after the last contact and compared with
 * the discrete-time theory ({@link PluckScene#modeHz(int)}).
 */
public final class AudioHapticPluck {
    /** Haptic rate, Hz. */
    public static final int HAPTIC_RATE = 1000;
    /** Frames per audio buffer. */
    public static final int BUFFER = 256;
    /** Gain of the listening point (output per model unit of y displacement). */
    public static final double LISTEN_GAIN = 30;
    /** Time left after the last contact before the pitch is measured, seconds. */
    public static final double SETTLE = 0.05;
    /** Partials measured and compared with theory. */
    public static final int PARTIALS = 3;
    /** The longest the run may take beyond the script, seconds, before it is called stuck. */
    static final double TIMEOUT_MARGIN = 20;

    /** The system property that gives the haptic loop a sketch's real-time scheduling ("true"). */
    static final String REALTIME_PROPERTY = "tactus.demo.realtime";

    private AudioHapticPluck() {
    }

    /** What a run produced. */
    public static final class Result {
        /** Files written. */
        public final Path wav, scenePng, pathPng, waveformPng, telemetryCsv, telemetryTxt;
        /** Measured frequency of partial m at index m - 1, Hz. */
        public final double[] measuredHz = new double[PARTIALS];
        /** Theoretical frequency of partial m at index m - 1, Hz. */
        public final double[] theoryHz = new double[PARTIALS];
        /** The tolerance on the fundamental: half the frequency resolution of the analysed stretch, cents. */
        public double toleranceCents;
        /** First sample of the analysed stretch, and its length. */
        public int analysedFrom, analysedCount;
        /** Audio rendered, seconds; wall time of the real-time run, seconds. */
        public double audioSeconds, wallSeconds;
        /** Largest absolute sample of the WAV. */
        public double peak;
        /** Largest force sent to the device, N. */
        public double maxForce;
        /** Haptic ticks recorded, and how many of them had the plectrum touching the string. */
        public int ticks, contactTicks;
        /** The haptic loop's telemetry at the end of the run. */
        public HapticTelemetry telemetry;
        /** Why the haptic loop stopped by itself, or null. */
        public String loopFailure;
        /** How the haptic loop's thread was scheduled ({@link HapticLoop#scheduling()}). */
        public String scheduling;
        /** Whether the real-time run kept time: the loop's ticks and the audio against its duration. */
        public TimingVerdict timing;

        Result(Path dir) {
            wav = dir.resolve("pluck.wav");
            scenePng = dir.resolve("pluck-scene.png");
            pathPng = dir.resolve("pluck-path.png");
            waveformPng = dir.resolve("pluck-waveform.png");
            telemetryCsv = dir.resolve("pluck-telemetry.csv");
            telemetryTxt = dir.resolve("pluck-telemetry.txt");
        }

        /** @return the measured fundamental's distance from theory, cents. */
        public double errorCents() {
            return Demo.cents(measuredHz[0], theoryHz[0]);
        }

        /** @return every file written. */
        public Path[] files() {
            return new Path[] {wav, scenePng, pathPng, waveformPng, telemetryCsv, telemetryTxt};
        }
    }

    /**
     * Runs the scene in real time and writes its files into {@code dir}.
     *
     * @return the files and figures
     */
    public static Result run(Path dir, PrintStream out) throws IOException {
        Result r = new Result(dir);
        int rate = PluckScene.AUDIO_RATE;
        out.printf(Locale.ROOT, "[3/3] Audio-haptic plucked string: %d Mass2DPlane masses, %d SpringDamper3D, "
                + "a plectrum (HapticInput3D) with a Contact3D to every mass, sphere of action %s (ALGO_UNITS)%n",
                PluckScene.MASSES, PluckScene.MASSES + 1, PluckScene.SPHERE);
        out.printf(Locale.ROOT, "  device: emulated Haply 2018 (M0 firmware) over an in-process link, the real "
                + "protocol code; the hand follows a script: %s%n", String.join(", ", PluckPath.phases()));
        out.printf(Locale.ROOT, "  haptic loop %d Hz (audio mode: position out, averaged force back through an "
                + "AvatarExchange); PhyUGen %d Hz, %d-frame buffers, paced in real time; %.1f s%n",
                HAPTIC_RATE, rate, BUFFER, PluckPath.DURATION);

        DeviceMapping mapping = new DeviceMapping();
        long clockOrigin = System.nanoTime();
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        double startX = mapping.modelX(emulator.x());
        double startY = mapping.modelY(emulator.y());
        PluckPath path = new PluckPath(startX, startY);
        emulator.setHand(Hand.scripted(path.deviceScript(mapping)));

        PhysicalModel mdl = PluckScene.build(new Vect3D(startX, startY, 0));
        PhyUGen ugen = new PhyUGen(mdl);
        ugen.listenToMass(PluckScene.mass(PluckScene.LISTENED_MASS), SteppedModel.Y, LISTEN_GAIN, 0);
        AvatarExchange exchange = new AvatarExchange(AvatarExchange.ForceMode.AVERAGE);
        ugen.attachAvatar(PluckScene.PLECTRUM, exchange);

        Board board = new Board(emulator.connect());
        Device device = new Device((byte) 5, board);
        HaplyPreset.HAPLY_2018.configure(device);
        device.device_set_parameters();
        ExchangeAvatar avatar = new ExchangeAvatar(exchange,
                (int) ((PluckPath.DURATION + TIMEOUT_MARGIN) * HAPTIC_RATE));
        HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), avatar);
        loop.setRate(HAPTIC_RATE);
        loop.setMode(HapticLoop.Mode.AUDIO);
        // -Dtactus.demo.realtime=true asks for the scheduling a sketch's HapticSession gets (SCHED_DEADLINE where
        // Linux allows it, else SCHED_FIFO, else normal priority). It is not the default: on a loaded 2-core machine
        // the in-process emulator's threads, at normal priority, then starve beside the loop and the scripted hand
        // misses the string. The summary says which policy the loop got either way.
        if (Boolean.getBoolean(REALTIME_PROPERTY)) {
            loop.setRealtimePriority(HapticSession.REALTIME_PRIORITY);
        }
        mapping.configure(loop);
        avatar.recordFrom(loop);

        int frames = (int) Math.round(PluckPath.DURATION * rate);
        AudioCapture capture = new AudioCapture(frames);
        SceneFrame scene = new SceneFrame();
        scene.draw(mdl, 0, 0, "");   // the first frame loads Java2D and the renderer's cache: not while plucking
        double[] sceneAt = {Double.NaN, Double.NaN};
        AudioOutput audio = new AudioOutput(new SilentAudioOut(1, BUFFER, rate));
        long wallStart = System.nanoTime();
        try {
            audio.addListener(capture);
            ugen.patch(audio);
            loop.start();
            // The main thread only watches: it draws a frame of the scene when the force during the first
            // pluck is the largest so far (the string is then bent furthest), from the lock-free snapshot.
            double[] f = new double[2];
            double[] p = new double[3];
            double best = 0;
            long deadline = wallStart + (long) ((PluckPath.DURATION + TIMEOUT_MARGIN) * 1e9);
            while (!capture.isFull() && loop.isRunning() && System.nanoTime() < deadline) {
                sleepMillis(5);
                double t = (System.nanoTime() - clockOrigin) * 1e-9;
                loop.deviceForce(f);
                double mag = Math.hypot(f[0], f[1]);
                if (t > 0.5 && t < 1.4 && mag > best && exchange.peekPosition(p)) {
                    best = mag;
                    scene.draw(mdl, f[0], f[1], String.format(Locale.ROOT,
                            "t = %.2f s, pluck down: the plectrum drags the string; force on the handle %.2f N",
                            t, mag));
                    sceneAt[0] = p[0];
                    sceneAt[1] = p[1];
                }
            }
        } finally {
            loop.close();
            audio.close();
            emulator.close();
        }
        r.wallSeconds = (System.nanoTime() - wallStart) * 1e-9;
        r.loopFailure = loop.failure();
        r.telemetry = loop.telemetry();
        r.scheduling = loop.scheduling();
        if (!capture.isFull()) {
            throw new Demo.DemoFailure("the audio-haptic run stopped early: " + capture.count() + " of " + frames
                    + " samples" + (r.loopFailure != null ? "; the haptic loop stopped: " + r.loopFailure : ""));
        }
        if (r.loopFailure != null) {
            throw new Demo.DemoFailure("the haptic loop stopped: " + r.loopFailure);
        }
        float[] samples = capture.samples();
        r.audioSeconds = frames / (double) rate;
        // the waveform plot is drawn on the audio's clock and the path plot on the loop's: an audio stall is also
        // how far the two plots disagree
        r.timing = TimingVerdict.of(r.telemetry, r.scheduling).withAudio(r.audioSeconds, r.wallSeconds);

        // ---- the WAV
        try (WavWriter w = new WavWriter(r.wav.toFile(), rate, 1, frames, WavWriter.Encoding.PCM_16)) {
            float[] frame = new float[1];
            for (float s : samples) {
                frame[0] = s;
                w.writeFrame(frame);
                r.peak = Math.max(r.peak, Math.abs(s));
            }
        }

        // ---- telemetry
        int n = avatar.finish();
        r.ticks = n;
        double[] tNanos = avatar.column(ExchangeAvatar.T_NANOS);
        double[] t = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = (tNanos[i] - clockOrigin) * 1e-9;
        }
        double[] fx = avatar.column(ExchangeAvatar.FORCE_X);
        double[] fy = avatar.column(ExchangeAvatar.FORCE_Y);
        double[] mfx = avatar.column(ExchangeAvatar.MODEL_FX);
        double[] mfy = avatar.column(ExchangeAvatar.MODEL_FY);
        double[] steps = avatar.column(ExchangeAvatar.AUDIO_STEPS);
        int lastContact = -1;
        for (int i = 0; i < n; i++) {
            r.maxForce = Math.max(r.maxForce, Math.hypot(fx[i], fy[i]));
            if (mfx[i] != 0 || mfy[i] != 0) {
                r.contactTicks++;
                lastContact = i;
            }
        }
        writeTelemetry(r, avatar, t, n, board, emulator);

        // ---- pitch: the free ringing after the last contact
        long released = lastContact >= 0 ? (long) steps[lastContact] : 0;
        r.analysedFrom = (int) Math.min(frames, released + BUFFER + Math.round(SETTLE * rate));
        r.analysedCount = frames - r.analysedFrom;
        if (lastContact < 0 || r.analysedCount < rate / 2) {
            throw new Demo.DemoFailure("the plectrum " + (lastContact < 0 ? "never touched the string"
                    : "left the string too late to measure its pitch (" + r.analysedCount + " samples left)"));
        }
        Pitch pitch = new Pitch(samples, r.analysedFrom, r.analysedCount, rate);
        double f1 = PluckScene.modeHz(1);
        for (int m = 1; m <= PARTIALS; m++) {
            r.theoryHz[m - 1] = PluckScene.modeHz(m);
            r.measuredHz[m - 1] = pitch.peakHz(r.theoryHz[m - 1] - 0.4 * f1, r.theoryHz[m - 1] + 0.4 * f1);
        }
        r.toleranceCents = Demo.cents(f1 + pitch.resolutionHz() / 2, f1);

        // ---- pictures
        if (Double.isNaN(sceneAt[0])) {
            throw new Demo.DemoFailure("no frame of the scene was drawn during the first pluck");
        }
        scene.save(r.scenePng.toFile(), sceneAt[0], sceneAt[1]);
        PathPlot.save(r.pathPng.toFile(), t, avatar.column(ExchangeAvatar.HANDLE_X),
                avatar.column(ExchangeAvatar.HANDLE_Y), fx, fy, n, mapping, path.phaseStarts(), PluckPath.phases());
        saveWaveform(r, samples, rate, (wallStart - clockOrigin) * 1e-9);

        // ---- summary
        out.printf(Locale.ROOT, "  ran %.2f s of wall time for %.2f s of audio (%d samples, peak %.3f)%n",
                r.wallSeconds, r.audioSeconds, frames, r.peak);
        out.println("  " + r.telemetry);
        out.println("  scheduling of the haptic loop: " + r.scheduling);
        out.println("  " + r.timing.text());
        out.printf(Locale.ROOT, "  %d ticks recorded, %d with the plectrum touching the string; largest force on "
                + "the handle %.2f N%n", r.ticks, r.contactTicks, r.maxForce);
        out.printf(Locale.ROOT, "  pitch, by FFT of pluck.wav over the free ringing after the last contact "
                + "(%.2f s to %.2f s, resolution %.3f Hz):%n", r.analysedFrom / (double) rate,
                frames / (double) rate, pitch.resolutionHz());
        for (int m = 1; m <= PARTIALS; m++) {
            out.printf(Locale.ROOT, "    partial %d: measured %.3f Hz, theory %.3f Hz, %+.2f cents%n", m,
                    r.measuredHz[m - 1], r.theoryHz[m - 1], Demo.cents(r.measuredHz[m - 1], r.theoryHz[m - 1]));
        }
        out.printf(Locale.ROOT, "    theory: cos w_m = 1 - 2 (kt/M) sin^2(m pi / (2 (N + 1))), kt = K (1 - l0/d); "
                + "tolerance on the fundamental %.2f cents (half the resolution)%n", r.toleranceCents);
        return r;
    }

    private static void sleepMillis(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new Demo.DemoFailure("interrupted");
        }
    }

    private static void writeTelemetry(Result r, ExchangeAvatar avatar, double[] t, int n, Board board,
                                       BoardEmulator emulator) throws IOException {
        int[] cols = {ExchangeAvatar.AUDIO_STEPS, ExchangeAvatar.STEPS_SPANNED, ExchangeAvatar.HANDLE_X,
            ExchangeAvatar.HANDLE_Y, ExchangeAvatar.TARGET_X, ExchangeAvatar.TARGET_Y, ExchangeAvatar.MODEL_FX,
            ExchangeAvatar.MODEL_FY, ExchangeAvatar.FORCE_X, ExchangeAvatar.FORCE_Y, ExchangeAvatar.TAU1,
            ExchangeAvatar.TAU2};
        try (BufferedWriter w = Files.newBufferedWriter(r.telemetryCsv, StandardCharsets.UTF_8)) {
            w.write(TELEMETRY_HEADER);
            w.write('\n');
            StringBuilder line = new StringBuilder(200);
            for (int i = 0; i < n; i++) {
                line.setLength(0);
                CsvNumbers.fixed(line, t[i], 6);
                for (int c : cols) {
                    double v = avatar.column(c)[i];
                    line.append(',');
                    if (c == ExchangeAvatar.AUDIO_STEPS || c == ExchangeAvatar.STEPS_SPANNED) {
                        line.append((long) v);
                    } else {
                        CsvNumbers.scientific(line, v, 6);
                    }
                }
                line.append('\n');
                w.append(line);
            }
        }
        HapticTelemetry tel = r.telemetry;
        try (BufferedWriter w = Files.newBufferedWriter(r.telemetryTxt, StandardCharsets.UTF_8)) {
            w.write("Tactus demo: haptic telemetry of the audio-haptic plucked string\n");
            w.write(tel.toString() + "\n");
            w.write("scheduling " + r.scheduling + "\n");
            w.write(String.format(Locale.ROOT, "nominal_hz %.1f%nachieved_hz %.2f%nticks %d%nseconds %.4f%n"
                            + "missed_steps %d%njitter_p50_us %.1f%njitter_p99_us %.1f%njitter_max_us %.1f%n"
                            + "compute_p50_us %.1f%ncompute_p99_us %.1f%ncompute_max_us %.1f%nstale_ticks %d%n"
                            + "fault_ticks %d%nclamped_ticks %d%nwatchdog_trips %d%n",
                    tel.nominalHz, tel.achievedHz, tel.ticks, tel.seconds, tel.missedSteps, tel.jitterP50Us,
                    tel.jitterP99Us, tel.jitterMaxUs, tel.computeP50Us, tel.computeP99Us, tel.computeMaxUs,
                    tel.staleTicks, tel.faultTicks, tel.clampedTicks, tel.watchdogTrips));
            w.write(String.format(Locale.ROOT, "board %s: frames_skipped %d, timeouts %d, id_mismatches %d%n",
                    board.describe(), board.framesSkipped(), board.timeouts(), board.idMismatches()));
            w.write(String.format(Locale.ROOT, "emulator: writes %d, replies %d%n", emulator.writes(),
                    emulator.replies()));
            w.write("per-tick record: " + r.telemetryCsv.getFileName() + " (" + TELEMETRY_HEADER + ")\n");
        }
    }

    /** Header of pluck-telemetry.csv: one row per haptic tick. */
    public static final String TELEMETRY_HEADER = "t_s,audio_steps,steps_in_tick,handle_x_m,handle_y_m,"
            + "model_x,model_y,model_fx,model_fy,force_x_N,force_y_N,tau1_Nm,tau2_Nm";

    private static void saveWaveform(Result r, float[] samples, int rate, double audioStart) {
        // min and max of every block of 32 samples, so that the plot keeps the envelope
        int block = 32;
        int blocks = samples.length / block;
        double[] time = new double[2 * blocks];
        double[] value = new double[2 * blocks];
        for (int b = 0; b < blocks; b++) {
            float lo = Float.POSITIVE_INFINITY;
            float hi = Float.NEGATIVE_INFINITY;
            for (int i = b * block; i < (b + 1) * block; i++) {
                lo = Math.min(lo, samples[i]);
                hi = Math.max(hi, samples[i]);
            }
            double tb = audioStart + (b + 0.5) * block / (double) rate;
            time[2 * b] = tb;
            value[2 * b] = lo;
            time[2 * b + 1] = tb;
            value[2 * b + 1] = hi;
        }
        new LineChart("pluck.wav: the sound of the string (mass " + PluckScene.LISTENED_MASS
                + ", y displacement x " + (int) LISTEN_GAIN + ", DC-blocked), 44.1 kHz", "time (s)", "sample")
                .series("waveform (min and max of every 32 samples)", time, value)
                .save(r.waveformPng.toFile(), Demo.PLOT_WIDTH, Demo.PLOT_HEIGHT);
    }
}
