package tactus.site;

import java.io.File;
import java.io.IOException;
import java.util.Arrays;
import java.util.Locale;

import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.audio.OfflineRenderer;
import tactus.audio.PhyUGen;
import tactus.audio.SteppedModel;
import tactus.haptics.AvatarLink;
import tactus.haptics.Board;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.HapticLoop;
import tactus.haptics.HapticSession;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;
import tactus.haptics.emulator.SimulatedInverse3;
import tactus.paramSystem;
import tactus.report.Fft;
import tactus.report.LineChart;

/**
 * Draws the docs site's pictures from real runs, at site-build time: a plucked string's waveform and spectrum
 * rendered offline by a {@code PhyUGen}, the haptic loop's tick periods on the emulated 2DIY, and the emulated
 * Inverse3's workspace. Run by {@code gradle site}: {@code SitePictures <out-folder>}.
 */
public final class SitePictures {
    private static final int WIDTH = 900;
    private static final int HEIGHT = 420;
    private static final int RATE = 44100;

    private SitePictures() {
    }

    /**
     * Writes {@code phyugen-waveform.png}, {@code phyugen-spectrum.png}, {@code haptic-loop-periods.png} and
     * {@code inverse3-workspace.png} into the folder.
     *
     * @param args the output folder
     * @throws Exception if a picture cannot be made or written
     */
    public static void main(String[] args) throws Exception {
        if (args.length != 1) {
            System.err.println("usage: SitePictures OUT_DIR");
            System.exit(2);
        }
        File out = new File(args[0]);
        if (!out.isDirectory() && !out.mkdirs()) {
            throw new IOException("cannot create " + out);
        }
        stringPictures(out);
        loopPeriods(out);
        inverse3Workspace(out);
        System.exit(0);   // the haptic loop's helper threads must not keep the JVM alive
    }

    /** The paper's plucked string (30 masses, algorithmic units at 44.1 kHz), plucked once, 1 s offline. */
    private static void stringPictures(File out) throws IOException {
        int masses = 30;
        double spacing = 0.1;
        PhysicalModel mdl = new PhysicalModel(RATE, 60, paramSystem.ALGO_UNITS);
        mdl.setGravity(0);
        mdl.setFriction(0.00001);
        mdl.addGround3D("g0", new Vect3D(0, 0, 0));
        for (int i = 1; i <= masses; i++) {
            mdl.addMass2DPlane("m" + i, 1, new Vect3D(i * spacing, 0, 0), new Vect3D());
        }
        mdl.addGround3D("g" + (masses + 1), new Vect3D((masses + 1) * spacing, 0, 0));
        for (int i = 0; i <= masses; i++) {
            String a = i == 0 ? "g0" : "m" + i;
            String b = i == masses ? "g" + (masses + 1) : "m" + (i + 1);
            mdl.addSpringDamper3D("s" + i, 0.05, 0.2, 0.0001, a, b);
        }
        mdl.init();
        mdl.triggerForceImpulse("m8", 0, 0.03, 0);
        PhyUGen ugen = new PhyUGen(mdl);
        ugen.listenToMass("m3", SteppedModel.Y, 30, 0);
        double seconds = 1.0;
        float[] samples = OfflineRenderer.renderToArray(ugen, RATE, 1, seconds)[0];

        int shown = RATE / 20;   // the first 50 ms
        double[] t = new double[shown];
        double[] y = new double[shown];
        for (int i = 0; i < shown; i++) {
            t[i] = 1000.0 * i / RATE;
            y[i] = samples[i];
        }
        new LineChart("A PhyUGen's output: the plucked string (30 masses), first 50 ms", "time (ms)", "sample")
                .series("mass m3, y", t, y)
                .save(new File(out, "phyugen-waveform.png"), WIDTH, HEIGHT);

        int n = Integer.highestOneBit(samples.length);
        double[] re = new double[n];
        double[] im = new double[n];
        for (int i = 0; i < n; i++) {
            double w = 0.5 - 0.5 * Math.cos(2 * Math.PI * i / (n - 1));   // Hann window
            re[i] = samples[i] * w;
        }
        Fft.transform(re, im);
        int bins = (int) (5000.0 * n / RATE);   // up to 5 kHz
        double[] f = new double[bins - 1];
        double[] db = new double[bins - 1];
        double max = 1e-30;
        for (int k = 1; k < bins; k++) {
            max = Math.max(max, Math.hypot(re[k], im[k]));
        }
        for (int k = 1; k < bins; k++) {
            f[k - 1] = (double) k * RATE / n;
            db[k - 1] = Math.max(-100, 20 * Math.log10(Math.hypot(re[k], im[k]) / max));
        }
        new LineChart("Its spectrum (first " + String.format(Locale.ROOT, "%.2f", (double) n / RATE)
                + " s, Hann window): the string's harmonics", "frequency (Hz)", "level (dB, 0 = strongest)")
                .series("mass m3, y", f, db)
                .save(new File(out, "phyugen-spectrum.png"), WIDTH, HEIGHT);
        System.out.println("pictures: phyugen-waveform.png, phyugen-spectrum.png");
    }

    /** Records when the loop calls its avatar link: once per tick, in an array allocated up front. */
    private static final class TickClock implements AvatarLink {
        final long[] at;
        volatile int count;

        TickClock(int capacity) {
            at = new long[capacity];
        }

        @Override
        public void setTarget(double x, double y, double z) {
            int c = count;
            if (c < at.length) {
                at[c] = System.nanoTime();
                count = c + 1;
            }
        }

        @Override
        public void takeForce(double[] out) {
            Arrays.fill(out, 0, 3, 0.0);
        }

        @Override
        public void step(int n) {
        }
    }

    /** The 1 kHz loop on the emulated 2DIY for 3 s: a histogram of the time between ticks. */
    private static void loopPeriods(File out) throws Exception {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        emulator.setHand(Hand.scripted((time, p) -> {
            p[0] = 0.02 * Math.sin(2 * Math.PI * time);
            p[1] = 0.08;
        }));
        Board board = new Board(emulator.connect());
        Device device = new Device((byte) 3, board);
        HaplyPreset.HAPLY_2018.configure(device);
        device.device_set_parameters();
        TickClock clock = new TickClock(3500);
        HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), clock);
        loop.setRate(1000);
        loop.setRealtimePriority(HapticSession.REALTIME_PRIORITY);   // what a sketch's HapticSession asks for
        loop.start();
        long end = System.nanoTime() + 3_500_000_000L;
        while (clock.count < clock.at.length && System.nanoTime() < end) {
            Thread.sleep(50);
        }
        String scheduling = loop.scheduling();
        String policy = scheduling.contains(" (") ? scheduling.substring(0, scheduling.indexOf(" (")) : scheduling;
        loop.close();
        int n = clock.count;
        if (n < 100) {
            throw new IllegalStateException("the haptic loop ticked only " + n + " times in 3.5 s");
        }
        // 0.05 ms bins from 0 to 3 ms; longer periods go into the last bin
        int bins = 60;
        double width = 0.05;
        double[] centre = new double[bins];
        double[] share = new double[bins];
        for (int b = 0; b < bins; b++) {
            centre[b] = (b + 0.5) * width;
        }
        int skip = 500;   // the first 0.5 s: the loop warms up
        int counted = 0;
        for (int i = skip + 1; i < n; i++) {
            double ms = (clock.at[i] - clock.at[i - 1]) / 1e6;
            share[Math.min(bins - 1, (int) (ms / width))]++;
            counted++;
        }
        for (int b = 0; b < bins; b++) {
            share[b] = 100.0 * share[b] / counted;
        }
        new LineChart("The haptic loop at 1 kHz on the emulated 2DIY: time between ticks (" + counted
                + " ticks, " + policy + " scheduling)", "period (ms; the last bin holds all longer)", "ticks (%)")
                .markers(true)
                .series("share of ticks per 0.05 ms", centre, share)
                .save(new File(out, "haptic-loop-periods.png"), WIDTH, HEIGHT);
        System.out.println("pictures: haptic-loop-periods.png (" + counted + " ticks, " + scheduling + ")");
    }

    /** Where the emulated Inverse3's handle can go: the handle sent far in every direction, seen from above and the side. */
    private static void inverse3Workspace(File out) throws IOException {
        SimulatedInverse3 device = new SimulatedInverse3();
        int directions = 720;
        double[] x = new double[directions + 1];
        double[] y = new double[directions + 1];
        double[] z = new double[directions + 1];
        double[] p = new double[3];
        double[] home = SimulatedInverse3.HOME;
        for (int i = 0; i <= directions; i++) {
            double a = 2 * Math.PI * i / directions;
            device.place(home[0] + Math.cos(a), home[1] + Math.sin(a), home[2]);   // 1 m away: clamped to the edge
            device.position(p);
            x[i] = 100 * p[0];
            y[i] = 100 * p[1];
            device.place(home[0] + Math.cos(a), home[1], home[2] + Math.sin(a));
            device.position(p);
            z[i] = 100 * p[2];
        }
        double[] xz = new double[directions + 1];
        for (int i = 0; i <= directions; i++) {
            double a = 2 * Math.PI * i / directions;
            device.place(home[0] + Math.cos(a), home[1], home[2] + Math.sin(a));
            device.position(p);
            xz[i] = 100 * p[0];
        }
        new LineChart("The emulated Inverse3's workspace (a box around its home position, service axes)",
                "x (cm)", "y or z (cm)")
                .series("seen from above: x, y", x, y)
                .series("seen from the front: x, z", xz, z)
                .series("home", new double[] {100 * home[0]}, new double[] {100 * home[1]})
                .markers(true)
                .save(new File(out, "inverse3-workspace.png"), WIDTH, (int) (HEIGHT * 1.3));
        System.out.println("pictures: inverse3-workspace.png");
    }
}
