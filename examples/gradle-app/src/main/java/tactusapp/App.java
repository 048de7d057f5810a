package tactusapp;

import java.io.File;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.locks.LockSupport;

import javax.sound.sampled.AudioInputStream;
import javax.sound.sampled.AudioSystem;
import javax.sound.sampled.UnsupportedAudioFileException;

import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.audio.AudioLibrary;
import tactus.audio.OfflineRenderer;
import tactus.audio.PhyUGen;
import tactus.audio.SteppedModel;
import tactus.audio.WavWriter;
import tactus.haptics.Board;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.HapticLoop;
import tactus.haptics.HapticSession;
import tactus.haptics.HapticTelemetry;
import tactus.haptics.PhysicalModelAvatar;
import tactus.haptics.TimingVerdict;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;

/**
 * Tactus in a plain JVM application, with no Processing: builds a string, renders one second of it to
 * a WAV file with no sound card and checks its pitch against theory, then drives an emulated Haply board through
 * the 1 kHz haptic loop for one second, a scripted hand dragging a chain of heavy masses, and prints what the
 * hand felt and how the loop kept time. The only argument is the output folder (default {@code build/app}).
 */
public final class App {
    private static final int AUDIO_RATE = 44100;
    private static final int BEADS = 20;
    private static final double K = 0.1;       // spring stiffness per step, ALGO_UNITS
    private static final double REST = 0.5;    // rest length, half the bead spacing 1: the string is under tension
    private static final double MASS = 1;
    /**
     * The fewest haptic ticks that still show the loop working: a tenth of the nominal 1000 in the second. How
     * many more it ran, and how late, is the timing verdict's business, not a failure.
     */
    static final int MIN_TICKS = 100;

    private App() {
    }

    public static void main(String[] args) throws Exception {
        File out = new File(args.length > 0 ? args[0] : "build/app");
        if (!out.isDirectory() && !out.mkdirs()) {
            throw new IOException("cannot create " + out);
        }
        List<String> failures = new ArrayList<>();
        audio(new File(out, "string.wav"), failures);
        TimingVerdict timing = haptics(failures);
        System.out.println(verdict(failures, timing));
        if (!failures.isEmpty()) {
            System.exit(1);
        }
    }

    /**
     * The application's last line: FAILED with every reason when something did not work (no sound, a wrong pitch, no
     * force on the hand, a loop that stopped or faulted), else OK; and whether the real-time run kept time, with what
     * to do when it did not. A late loop on a busy machine is not a failure: the model still computed the same.
     *
     * @param failures what did not work, one reason each
     * @param timing the haptic loop's timing, or null if it did not run
     */
    static String verdict(List<String> failures, TimingVerdict timing) {
        String time = timing == null ? "" : timing.onTime() ? "; " + timing.text() : ", but " + timing.text();
        if (!failures.isEmpty()) {
            return "gradle-app: FAILED: " + String.join("; ", failures) + time;
        }
        return "gradle-app: OK: the string's pitch matches theory and the hand felt the chain" + time;
    }

    // ------------------------------------------------------------------------------------------------- audio

    /** A string of BEADS masses between two fixed ends, started in the shape of its first mode, at 44.1 kHz. */
    static PhysicalModel string() {
        PhysicalModel m = new PhysicalModel(AUDIO_RATE);
        m.addGround3D("g0", new Vect3D(0, 0, 0));
        for (int i = 1; i <= BEADS; i++) {
            double shape = Math.sin(Math.PI * i / (BEADS + 1));   // the first mode's shape: one clean pitch
            m.addMass3D("m" + i, MASS, new Vect3D(i, 0.02 * shape, 0), new Vect3D());
        }
        m.addGround3D("g1", new Vect3D(BEADS + 1, 0, 0));
        for (int i = 0; i <= BEADS; i++) {
            String a = i == 0 ? "g0" : "m" + i;
            String b = i == BEADS ? "g1" : "m" + (i + 1);
            m.addSpringDamper3D("k" + i, REST, K, 0.0002, a, b);
        }
        m.init();
        return m;
    }

    /**
     * Theory: across the string a spring of stiffness K, rest length l0 and length d pulls back with the
     * tension stiffness K (1 - l0 / d); for this scheme, mode n of a fixed-fixed chain of N beads then turns by
     * w per step with sin(w/2) = sqrt(K (1 - l0/d) / M) sin(n pi / (2 (N + 1))).
     */
    static double fundamentalHz() {
        double transverse = K * (1 - REST / 1.0);
        double w = 2 * Math.asin(Math.sqrt(transverse / MASS) * Math.sin(Math.PI / (2 * (BEADS + 1))));
        return w * AUDIO_RATE / (2 * Math.PI);
    }

    static void audio(File wav, List<String> failures) throws IOException, UnsupportedAudioFileException {
        PhyUGen ugen = AudioLibrary.newPhyUGen(string());   // says to add Minim if it is missing
        ugen.listenToMass("m" + BEADS / 2, SteppedModel.Y, 20, 0);
        ugen.setDcBlocker(0.999);
        OfflineRenderer.Result r = OfflineRenderer.renderToWav(ugen, AUDIO_RATE, 1, 1.0, wav,
                WavWriter.Encoding.PCM_16, System.out);
        System.out.println("audio: wrote " + wav + ": " + r);
        double measured = zeroCrossingPitch(wav);
        double theory = fundamentalHz();
        double cents = 1200 * Math.log(measured / theory) / Math.log(2);
        System.out.printf(Locale.ROOT, "audio: pitch %.2f Hz measured, %.2f Hz in theory (%+.1f cents)%n",
                measured, theory, cents);
        if (!(r.peak > 1e-3)) {
            failures.add(String.format(Locale.ROOT, "the string made no sound (peak %.2g)", r.peak));
        } else if (!(Math.abs(cents) < 5)) {
            failures.add(String.format(Locale.ROOT, "the string's pitch %.2f Hz is %+.1f cents from theory %.2f Hz "
                    + "(bound 5 cents)", measured, cents, theory));
        }
    }

    /** Pitch from the rising zero crossings of the second half of a 16-bit mono WAV, interpolated. */
    static double zeroCrossingPitch(File wav) throws IOException, UnsupportedAudioFileException {
        byte[] b;
        float rate;
        try (AudioInputStream in = AudioSystem.getAudioInputStream(wav)) {
            rate = in.getFormat().getSampleRate();
            b = in.readAllBytes();
        }
        int n = b.length / 2;
        double first = -1;
        double last = -1;
        int count = 0;
        double prev = 0;
        for (int i = n / 2; i < n; i++) {
            double v = (short) ((b[2 * i] & 0xFF) | (b[2 * i + 1] << 8));
            if (i > n / 2 && prev < 0 && v >= 0) {
                double t = i - 1 + prev / (prev - v);
                if (first < 0) {
                    first = t;
                } else {
                    count++;
                    last = t;
                }
            }
            prev = v;
        }
        return count > 0 ? count * rate / (last - first) : 0;
    }

    // ---------------------------------------------------------------------------------------------- haptics

    /** The paper's heavy mass chain: an avatar holding a chain of ten heavy masses, at 1 kHz. */
    static PhysicalModel chain() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addHapticInput3D("hapticMass", new Vect3D(), 10);
        for (int i = 0; i < 10; i++) {
            m.addMass3D("m" + i, 20, new Vect3D(0.1 * (i + 1), 0, 0), new Vect3D());
        }
        for (int i = 0; i < 9; i++) {
            m.addSpringDamper3D("k" + i, 0.1, 0.003, 0.05, "m" + i, "m" + (i + 1));
        }
        m.addSpringDamper3D("grip", 0.1, 0.003, 0.05, "hapticMass", "m0");
        m.init();
        return m;
    }

    /** Runs the loop for one second of emulated time; adds what did not work to {@code failures}. */
    static TimingVerdict haptics(List<String> failures) {
        double y0 = 0.08;      // metres: the handle's start, in the middle of the workspace
        double radius = 0.02;  // the hand draws a 2 cm circle once a second
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        emulator.setHand(Hand.scripted((t, p) -> {
            double a = 2 * Math.PI * t;
            p[0] = radius * Math.sin(a);
            p[1] = y0 + radius * (1 - Math.cos(a));
        }));
        Board board = new Board(emulator.connect());
        try {
            Device device = new Device((byte) 1, board);
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(),
                    new PhysicalModelAvatar(chain(), "hapticMass"));
            loop.setOrigin(0, -200 * y0, 0);   // the start pose is the model's origin
            loop.setRealtimePriority(HapticSession.REALTIME_PRIORITY);   // what a sketch's HapticSession asks for
            loop.start();
            double[] f = new double[2];
            double peak = 0;
            double sum = 0;
            int samples = 0;
            while (emulator.time() < 1.0 && loop.isRunning()) {
                LockSupport.parkNanos(2_000_000);
                loop.deviceForce(f);
                double magnitude = Math.hypot(f[0], f[1]);
                peak = Math.max(peak, magnitude);
                sum += magnitude;
                samples++;
            }
            String failure = loop.failure();
            loop.close();
            HapticTelemetry tm = loop.telemetry();
            System.out.printf(Locale.ROOT, "haptics: %d ticks in %.2f s of emulated time, %.0f Hz achieved, "
                    + "%d missed; force on the hand: mean %.3f N, peak %.3f N%n", tm.ticks, emulator.time(),
                    tm.achievedHz, tm.missedSteps, samples > 0 ? sum / samples : 0, peak);
            System.out.println("haptics: " + tm);
            System.out.println("haptics: scheduling: " + loop.scheduling());
            if (failure != null) {
                failures.add("the haptic loop stopped: " + failure);
            }
            if (tm.ticks < MIN_TICKS) {
                failures.add(String.format(Locale.ROOT, "the haptic loop ran %d ticks in %.2f s, fewer than the %d needed"
                        + " to judge it (the machine is too busy to run it at all)", tm.ticks, tm.seconds, MIN_TICKS));
            }
            if (!(peak > 0)) {
                failures.add("the hand felt no force from the chain");
            }
            if (tm.faultTicks > 0) {
                failures.add(tm.faultTicks + " haptic ticks faulted (see the telemetry above)");
            }
            return TimingVerdict.of(tm, loop.scheduling());
        } finally {
            board.close();
            emulator.close();
        }
    }
}
