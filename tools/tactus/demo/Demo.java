package tactus.demo;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import tactus.DivergenceException;
import tactus.Mass;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;
import tactus.report.LineChart;

/**
 * The headless demo behind {@code gradle demo}: three models from the paper, with a printed summary,
 * CSV files, PNG plots and a WAV file. The first two are simulated offline for two seconds each; the
 * third, the audio-haptic plucked string ({@link AudioHapticPluck}), runs in real time through the whole
 * chain: an emulated Haply, the 1 kHz haptic loop and a 44.1 kHz {@code PhyUGen}.
 *
 * <ol>
 *   <li><b>Figure 4</b> of the paper, in algorithmic units: one {@code Mass3D} ("mass", m = 100) at
 *       the origin, launched upward at 1 unit/s, between two {@code Ground3D} at x = &plusmn;1.5,
 *       tied to them by two {@code SpringDamper3D} of rest length 1 (K = 0.1 and 0.15, Z = 0.01).
 *       The springs are stretched and unequal, so the mass swings along x around x = -0.1 and
 *       sways along z. Simulated at 300 steps/s (display rate 60 frames/s).</li>
 *   <li><b>A plucked string</b>, in SI units ({@code REAL_UNITS}) at the audio rate 44.1 kHz: 49
 *       beads of 0.1 g ({@code Mass2DPlane}, they move in the x-y plane) 1 cm apart, between two
 *       {@code Ground3D} 50 cm apart, joined by 50 {@code SpringDamper3D} (K = 54000 N/m,
 *       Z = 0.01 N&middot;s/m, rest length 1 mm, so each spring is stretched to 1 cm and the
 *       string is under about 490 N of tension). Air friction 0.0002 N&middot;s/m makes it ring
 *       for a few seconds. It is plucked by starting it from a triangle, 3 mm high in the middle,
 *       at rest. Its lowest note is close to A3 (220 Hz).</li>
 *   <li><b>The audio-haptic plucked string</b> of the paper ({@link PluckScene}): a string plucked by a
 *       plectrum with a sphere of action, held by an emulated Haply whose scripted hand goes down through
 *       the string, back up, then strums. It writes {@code pluck.wav}, a frame of the scene drawn by the
 *       library's renderer, the hand path with the force felt along it, the waveform and the haptic
 *       telemetry, and compares the pitch of the WAV with theory.</li>
 * </ol>
 *
 * <p>The string's measured fundamental (from the upward zero crossings of its middle bead) is
 * compared with the lowest mode of the discrete scheme. For N beads of mass M between fixed ends,
 * a spring of stiffness K and rest length l0 stretched to length d gives a transverse (sideways)
 * stiffness {@code Kt = K (1 - l0/d)} (tension over length), and the explicit scheme's lowest
 * transverse mode {@code w1} (radians per step) solves
 * {@code 2 (1 - cos w1) M = 4 Kt sin^2(pi / (2 (N + 1)))}, with K in per-step units
 * ({@code K / fs^2} for K in N/m). Then {@code f1 = w1 fs / (2 pi)}.
 *
 * <p>Usage: {@code java -Djava.awt.headless=true tactus.demo.Demo [outputFolder]}; the folder
 * defaults to {@code build/demo}. The exit status is 0 on success and 1 (with a message on the
 * error stream) on failure, 2 for a usage error.
 */
public final class Demo {

    /** The output folder used when none is given. */
    public static final String DEFAULT_OUTPUT = "build/demo";
    /** Simulated duration of each model, in seconds. */
    public static final double SECONDS = 2.0;
    /** Width of every PNG plot, in pixels. */
    public static final int PLOT_WIDTH = 900;
    /** Height of every PNG plot, in pixels. */
    public static final int PLOT_HEIGHT = 500;

    // ---------------------------------------------------------------- Figure 4 (ALGO_UNITS)

    /** Figure 4: simulation rate, steps per second. */
    public static final int FIG4_SIM_RATE = 300;
    /** Figure 4: display rate, frames per second. */
    public static final int FIG4_DISPLAY_RATE = 60;
    /** Figure 4: the inertia of "mass" (algorithmic units). */
    public static final double FIG4_MASS = 100.0;
    /** Figure 4: the fixed points are at x = +dist and x = -dist. */
    public static final double FIG4_DIST = 1.5;
    /** Figure 4: rest length of both springs (the paper's value). */
    public static final double FIG4_REST = 1.0;
    /** Figure 4: stiffness of "spring1" and "spring2", per step squared (the paper's values). */
    public static final double FIG4_K1 = 0.1;
    /** Figure 4: stiffness of "spring2". */
    public static final double FIG4_K2 = 0.15;
    /** Figure 4: damping of both springs, per step (the paper's value). */
    public static final double FIG4_Z = 0.01;

    // ---------------------------------------------------------------- plucked string (REAL_UNITS)

    /** String: simulation rate (audio rate), steps per second. */
    public static final int STRING_RATE = 44100;
    /** String: number of moving beads (Mass2DPlane) between the two fixed ends. */
    public static final int STRING_BEADS = 49;
    /** String: mass of one bead, kg. */
    public static final double BEAD_MASS = 1e-4;
    /** String: distance between neighbouring beads (and the ends) at rest, m. */
    public static final double BEAD_SPACING = 0.01;
    /** String: rest length of each spring, m; shorter than the spacing, so the string is under tension. */
    public static final double SPRING_REST = 0.001;
    /** String: stiffness of each spring, N/m. */
    public static final double SPRING_K = 54000.0;
    /** String: damping of each spring, N·s/m (it acts along the spring only). */
    public static final double SPRING_Z = 0.01;
    /** String: air friction of the model, N·s/m. */
    public static final double AIR_FRICTION = 2e-4;
    /** String: height of the triangular pluck at the middle of the string, m. */
    public static final double PLUCK_HEIGHT = 0.003;
    /** String: the beads written to string.csv and plotted, by number (1 is next to the left end). */
    public static final int[] LISTENED_BEADS = {5, 13, 25};
    /** String: the bead whose zero crossings give the measured fundamental (the middle one). */
    public static final int PITCH_BEAD = 25;
    /** The demo fails if the measured fundamental is farther than this from theory, in cents. */
    public static final double PITCH_TOLERANCE_CENTS = 5.0;

    private Demo() {
    }

    /**
     * Runs the demo and exits the JVM with its status (only when it is not 0, so that a caller in
     * the same JVM, such as Gradle's runner, sees a normal return on success).
     *
     * @param args at most one argument: the output folder (default {@value #DEFAULT_OUTPUT})
     */
    public static void main(String[] args) {
        int status = run(args, System.out, System.err);
        if (status != 0) {
            System.exit(status);
        }
    }

    /**
     * Runs the demo without exiting: parses the arguments, runs the three models, writes the files and
     * prints the summary to {@code out}; problems are printed to {@code err}.
     *
     * @return 0 on success, 1 if something failed, 2 for a usage error
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        if (args.length > 1 || (args.length == 1 && (args[0].equals("-h") || args[0].equals("--help")))) {
            err.println("usage: java -Djava.awt.headless=true tactus.demo.Demo [outputFolder]");
            err.println("  writes figure4.csv, figure4.png, string.csv, string.png, string-shape.png, pluck.wav,");
            err.println("  pluck-scene.png, pluck-path.png, pluck-waveform.png, pluck-telemetry.csv and .txt");
            err.println("  into outputFolder (default " + DEFAULT_OUTPUT + ")");
            return 2;
        }
        Path dir;
        try {
            dir = Paths.get(args.length == 1 ? args[0] : DEFAULT_OUTPUT).toAbsolutePath().normalize();
        } catch (InvalidPathException e) {
            err.println("Demo failed: \"" + args[0] + "\" is not a valid folder name: " + e.getMessage());
            return 1;
        }
        try {
            run(dir, out);
            return 0;
        } catch (DemoFailure e) {
            err.println("Demo failed: " + e.getMessage());
            return 1;
        } catch (DivergenceException e) {
            err.println("Demo failed: the simulation diverged: " + e.getMessage());
            return 1;
        } catch (IOException | UncheckedIOException e) {
            err.println("Demo failed: could not write the output in " + args0(args) + ": " + e);
            return 1;
        } catch (LinkageError e) {
            if (String.valueOf(e.getMessage()).startsWith("processing/")) {
                err.println("Demo failed: Processing's core library is not on the classpath (missing class "
                        + e.getMessage() + "). Run it with 'gradle demo', or add core.jar to -cp.");
            } else {
                err.println("Demo failed: " + e);
                e.printStackTrace(err);
            }
            return 1;
        } catch (Exception e) {
            err.println("Demo failed: " + e);
            e.printStackTrace(err);
            return 1;
        }
    }

    private static String args0(String[] args) {
        return args.length == 1 ? args[0] : DEFAULT_OUTPUT;
    }

    /** A failure with a message meant for the user. */
    static final class DemoFailure extends IllegalStateException {
        private static final long serialVersionUID = 1L;

        DemoFailure(String message) {
            super(message);
        }
    }

    /** What one run of the demo produced: the files written and the string's pitch figures. */
    public static final class Result {
        /** The files written, as absolute paths. */
        public final Path figure4Csv, figure4Png, stringCsv, stringPng, stringShapePng;
        /** What the audio-haptic plucked string produced (its files, pitch and telemetry). */
        public AudioHapticPluck.Result pluck;
        /** The string's fundamental from its zero crossings, Hz. */
        public final double measuredHz;
        /** The string's fundamental from the discrete-scheme theory, Hz. */
        public final double theoryHz;
        /** The measured fundamental relative to theory, in cents (1/100 of a semitone). */
        public final double errorCents;

        Result(Path dir, double measuredHz, double theoryHz) {
            this.figure4Csv = dir.resolve("figure4.csv");
            this.figure4Png = dir.resolve("figure4.png");
            this.stringCsv = dir.resolve("string.csv");
            this.stringPng = dir.resolve("string.png");
            this.stringShapePng = dir.resolve("string-shape.png");
            this.measuredHz = measuredHz;
            this.theoryHz = theoryHz;
            this.errorCents = cents(measuredHz, theoryHz);
        }
    }

    /**
     * Runs the three models, writes their files into {@code dir} (created if needed) and prints the
     * summary to {@code out}.
     *
     * @return the files written and the string's pitch figures
     * @throws IOException if a file cannot be written
     * @throws IllegalStateException (a {@code DemoFailure}) if a simulation diverges, a file is
     *                               missing afterwards, or the pitch is off by more than
     *                               {@value #PITCH_TOLERANCE_CENTS} cents
     */
    public static Result run(Path dir, PrintStream out) throws IOException {
        if (Files.exists(dir) && !Files.isDirectory(dir)) {
            throw new DemoFailure("the output folder " + dir + " is a file, not a folder");
        }
        Files.createDirectories(dir);
        out.println("Tactus " + PhysicalModel.version()
                + " demo: three models from \"Fast audio-haptic prototyping with mass-interaction physics\"");
        out.println("Output folder: " + dir);
        out.println();
        runFigure4(dir, out);
        out.println();
        Result r = runString(dir, out);
        out.println();
        r.pluck = AudioHapticPluck.run(dir, out);
        out.println();
        List<Path> files = new ArrayList<>(Arrays.asList(r.figure4Csv, r.figure4Png, r.stringCsv, r.stringPng,
                r.stringShapePng));
        files.addAll(Arrays.asList(r.pluck.files()));
        out.println("Files written:");
        for (Path f : files) {
            if (!Files.isRegularFile(f) || Files.size(f) == 0) {
                throw new DemoFailure("expected output file " + f + " is missing or empty");
            }
            out.printf(Locale.ROOT, "  %-60s %,10d bytes%n", f, Files.size(f));
        }
        if (!(Math.abs(r.errorCents) <= PITCH_TOLERANCE_CENTS)) {
            throw new DemoFailure(String.format(Locale.ROOT,
                    "the string's measured fundamental %.3f Hz is %+.2f cents from the theoretical %.3f Hz "
                            + "(tolerance %.1f cents)", r.measuredHz, r.errorCents, r.theoryHz,
                    PITCH_TOLERANCE_CENTS));
        }
        AudioHapticPluck.Result p = r.pluck;
        if (!(Math.abs(p.errorCents()) <= p.toleranceCents)) {
            throw new DemoFailure(String.format(Locale.ROOT,
                    "the plucked string's measured fundamental %.3f Hz (pluck.wav) is %+.2f cents from the "
                            + "theoretical %.3f Hz (tolerance %.2f cents)", p.measuredHz[0], p.errorCents(),
                    p.theoryHz[0], p.toleranceCents));
        }
        out.printf(Locale.ROOT, "Audio-haptic pluck: %.2f s of audio in %.2f s of wall time; fundamental of "
                + "pluck.wav %.3f Hz, theory %.3f Hz (%+.2f cents)%n", p.audioSeconds, p.wallSeconds,
                p.measuredHz[0], p.theoryHz[0], p.errorCents());
        out.println(finalLine(p.timing));
        return r;
    }

    /**
     * The demo's last line: what it checked (files, pitches) and whether the real-time run kept time; a late run is
     * said to be late, with the reasons and what to do, not passed over.
     */
    static String finalLine(tactus.haptics.TimingVerdict timing) {
        String checked = "all files written, the strings' pitches match theory";
        if (timing.onTime()) {
            return "Demo finished: " + checked + ", and " + timing.text() + ".";
        }
        return "Demo finished: " + checked + ", but " + timing.text();
    }

    // ================================================================ Figure 4

    /**
     * Builds the model of the paper's Figure 4, with the mass at {@code start} moving at
     * {@code velocity} (units per second).
     */
    static PhysicalModel buildFigure4(Vect3D start, Vect3D velocity) {
        PhysicalModel mdl = new PhysicalModel(FIG4_SIM_RATE, FIG4_DISPLAY_RATE, paramSystem.ALGO_UNITS);
        mdl.addMass3D("mass", FIG4_MASS, start, velocity);
        mdl.addGround3D("ground1", new Vect3D(FIG4_DIST, 0., 0.));
        mdl.addGround3D("ground2", new Vect3D(-FIG4_DIST, 0., 0.));
        mdl.addSpringDamper3D("spring1", FIG4_REST, FIG4_K1, FIG4_Z, "mass", "ground1");
        mdl.addSpringDamper3D("spring2", FIG4_REST, FIG4_K2, FIG4_Z, "mass", "ground2");
        mdl.init();
        return mdl;
    }

    /** @return the x where the two springs of Figure 4 balance (y = z = 0). */
    static double figure4Equilibrium() {
        // K1 (D - x - l) = K2 (D + x - l)  =>  x = (K1 - K2) (D - l) / (K1 + K2)
        return (FIG4_K1 - FIG4_K2) * (FIG4_DIST - FIG4_REST) / (FIG4_K1 + FIG4_K2);
    }

    private static void runFigure4(Path dir, PrintStream out) throws IOException {
        out.println("[1/3] Figure 4: one Mass3D between two Ground3D, joined by two SpringDamper3D (ALGO_UNITS)");
        out.printf(Locale.ROOT, "  simRate %d Hz, dispRate %d Hz, m = %s, grounds at x = +/-%s, "
                        + "springs: rest %s, K %s and %s, Z %s%n", FIG4_SIM_RATE, FIG4_DISPLAY_RATE,
                num(FIG4_MASS), num(FIG4_DIST), num(FIG4_REST), num(FIG4_K1), num(FIG4_K2), num(FIG4_Z));
        out.println("  the mass starts at the origin moving up (+z) at 1 unit/s");

        PhysicalModel mdl = buildFigure4(new Vect3D(0., 0., 0.), new Vect3D(0., 0., 1.));
        double xEq = figure4Equilibrium();
        double restEnergy = buildFigure4(new Vect3D(xEq, 0., 0.), new Vect3D()).getTotalEnergy();
        Mass mass = mdl.getMass("mass");
        out.println("  " + mdl.describeStability());

        int steps = (int) Math.round(SECONDS * FIG4_SIM_RATE);
        double[] t = new double[steps + 1];
        double[][] pos = new double[3][steps + 1];
        double[] e0 = energies(mdl);
        Vect3D p = new Vect3D();
        long wall = System.nanoTime();
        for (int n = 0; n <= steps; n++) {
            if (n > 0) {
                mdl.computeStep();
            }
            mass.getPosition(p);
            t[n] = (double) n / FIG4_SIM_RATE;
            pos[0][n] = p.x;
            pos[1][n] = p.y;
            pos[2][n] = p.z;
        }
        double seconds = (System.nanoTime() - wall) * 1e-9;
        requireFinite("Figure 4", "mass", pos);
        double[] e1 = energies(mdl);

        out.printf(Locale.ROOT, "  simulated %s s (%d steps) in %.3f s%n", num(SECONDS), steps, seconds);
        out.printf(Locale.ROOT, "  final position of \"mass\": x = %+.5f, y = %+.5f, z = %+.5f%n", p.x, p.y, p.z);
        printEnergies(out, "algorithmic units: mass x (units/step)^2", e0, e1, restEnergy,
                String.format(Locale.ROOT, "total minus the mass at rest at x = %.3f", xEq));

        // Along x both springs pull straight: 2 (1 - cos w) m = K1 + K2.
        double[] dx = new double[steps + 1];
        for (int n = 0; n <= steps; n++) {
            dx[n] = pos[0][n] - xEq;
        }
        double wx = Math.acos(1 - (FIG4_K1 + FIG4_K2) / (2 * FIG4_MASS));
        double theoryX = wx * FIG4_SIM_RATE / (2 * Math.PI);
        double measuredX = fundamentalFromZeroCrossings(dx, FIG4_SIM_RATE);
        out.printf(Locale.ROOT, "  swing along x around x = %.3f: measured %.3f Hz, theory %.3f Hz "
                        + "(2 (1 - cos w) m = K1 + K2), error %+.1f cents%n",
                xEq, measuredX, theoryX, cents(measuredX, theoryX));

        writeCsv(dir.resolve("figure4.csv"), "t_s,mass_x,mass_y,mass_z", t, pos, 7);
        new LineChart("Figure 4: position of \"mass\" (simRate 300 Hz, ALGO_UNITS)", "time (s)",
                "position (model units)")
                .series("x", t, pos[0])
                .series("z", t, pos[2])
                .save(dir.resolve("figure4.png").toFile(), PLOT_WIDTH, PLOT_HEIGHT);
        out.println("  wrote figure4.csv (t_s, mass_x, mass_y, mass_z at every step) and figure4.png");
    }

    // ================================================================ plucked string

    /** @return the name of bead {@code i} (1 to {@value #STRING_BEADS}). */
    static String bead(int i) {
        return "str" + i;
    }

    /** @return the length of the string between its fixed ends, m. */
    static double stringLength() {
        return (STRING_BEADS + 1) * BEAD_SPACING;
    }

    /**
     * Builds the string, with its beads displaced sideways (along y) into a triangle of height
     * {@code pluck} at the middle, at rest. {@code pluck = 0} gives the straight string at rest.
     */
    static PhysicalModel buildString(double pluck) {
        PhysicalModel mdl = new PhysicalModel(STRING_RATE, 60, paramSystem.REAL_UNITS);
        mdl.setFriction(AIR_FRICTION);
        double length = stringLength();
        double half = length / 2;
        mdl.addGround3D("left", new Vect3D(0., 0., 0.));
        for (int i = 1; i <= STRING_BEADS; i++) {
            double x = i * BEAD_SPACING;
            double y = pluck * (1 - Math.abs(x - half) / half);
            mdl.addMass2DPlane(bead(i), BEAD_MASS, new Vect3D(x, y, 0.), new Vect3D());
        }
        mdl.addGround3D("right", new Vect3D(length, 0., 0.));
        for (int i = 0; i <= STRING_BEADS; i++) {
            String a = i == 0 ? "left" : bead(i);
            String b = i == STRING_BEADS ? "right" : bead(i + 1);
            mdl.addSpringDamper3D("spring" + i, SPRING_REST, SPRING_K, SPRING_Z, a, b);
        }
        mdl.init();
        return mdl;
    }

    /**
     * The lowest transverse mode of a stretched chain of {@code n} equal masses between fixed ends,
     * for the explicit scheme: {@code 2 (1 - cos w) M = 4 Kt sin^2(pi / (2 (n + 1)))} with
     * {@code Kt = K (1 - l0/d)}.
     *
     * @param n       number of moving masses
     * @param mass    mass of each
     * @param kAlgo   spring stiffness in per-step units (K in N/m divided by fs^2)
     * @param rest    spring rest length l0
     * @param spacing spring length d at rest (the string is straight)
     * @param fs      simulation rate, steps per second
     * @return the frequency of the lowest mode, Hz
     */
    public static double chainFundamental(int n, double mass, double kAlgo, double rest, double spacing,
                                          double fs) {
        double kt = kAlgo * (1 - rest / spacing);
        double s = Math.sin(Math.PI / (2.0 * (n + 1)));
        double w = Math.acos(1 - 2 * kt * s * s / mass);
        return w * fs / (2 * Math.PI);
    }

    private static Result runString(Path dir, PrintStream out) throws IOException {
        int n = STRING_BEADS;
        out.printf(Locale.ROOT, "[2/3] Plucked string: %d Mass2DPlane beads, %d SpringDamper3D, 2 Ground3D "
                + "(REAL_UNITS, SI)%n", n, n + 1);
        out.printf(Locale.ROOT, "  simRate %d Hz; length %s m; beads %s g, %s cm apart; springs K %s N/m, "
                        + "Z %s N*s/m, rest %s mm; air friction %s N*s/m%n", STRING_RATE, num(stringLength()),
                num(BEAD_MASS * 1e3), num(BEAD_SPACING * 100), num(SPRING_K), num(SPRING_Z),
                num(SPRING_REST * 1e3), num(AIR_FRICTION));
        double tension = SPRING_K * (BEAD_SPACING - SPRING_REST);
        out.printf(Locale.ROOT, "  tension %.1f N; plucked by starting from a triangle %s mm high in the middle, "
                + "at rest%n", tension, num(PLUCK_HEIGHT * 1e3));

        PhysicalModel mdl = buildString(PLUCK_HEIGHT);
        double restEnergy = buildString(0).getTotalEnergy();
        out.println("  " + mdl.describeStability());
        Mass[] beads = new Mass[n + 1];
        for (int i = 1; i <= n; i++) {
            beads[i] = mdl.getMass(bead(i));
        }
        int[] listened = LISTENED_BEADS;
        int steps = (int) Math.round(SECONDS * STRING_RATE);
        double[] t = new double[steps + 1];
        double[][] ys = new double[listened.length][steps + 1];

        // Snapshots of the whole string over the first period (theory), for string-shape.png.
        double theory = chainFundamental(n, BEAD_MASS, SPRING_K / ((double) STRING_RATE * STRING_RATE),
                SPRING_REST, BEAD_SPACING, STRING_RATE);
        int shapes = 5;
        int[] shapeStep = new int[shapes];
        double[][] shapeX = new double[shapes][n + 2];
        double[][] shapeY = new double[shapes][n + 2];
        for (int k = 0; k < shapes; k++) {
            shapeStep[k] = (int) Math.round(k / 8.0 * STRING_RATE / theory);
        }

        double[] e0 = energies(mdl);
        Vect3D p = new Vect3D();
        Progress progress = new Progress(out, "string", steps);
        int nextShape = 0;
        for (int s = 0; s <= steps; s++) {
            if (s > 0) {
                mdl.computeStep();
            }
            t[s] = (double) s / STRING_RATE;
            for (int j = 0; j < listened.length; j++) {
                ys[j][s] = beads[listened[j]].getPosition(p).y;
            }
            if (nextShape < shapes && s == shapeStep[nextShape]) {
                double[] sx = shapeX[nextShape];
                double[] sy = shapeY[nextShape];
                sx[n + 1] = stringLength();
                for (int i = 1; i <= n; i++) {
                    beads[i].getPosition(p);
                    sx[i] = p.x;
                    sy[i] = p.y;
                }
                nextShape++;
            }
            if ((s & 4095) == 0) {
                progress.update(s);
            }
        }
        double seconds = progress.elapsed();
        double[] e1 = energies(mdl);
        double[][] finalPos = new double[listened.length][];
        for (int j = 0; j < listened.length; j++) {
            Vect3D q = beads[listened[j]].getPosition();
            finalPos[j] = new double[] {q.x, q.y};
        }
        requireFinite("the plucked string", "listened beads", ys);

        out.printf(Locale.ROOT, "  simulated %s s (%,d steps of %d beads and %d springs) in %.2f s%n",
                num(SECONDS), steps, n, n + 1, seconds);
        out.print("  final positions (m):");
        for (int j = 0; j < listened.length; j++) {
            out.printf(Locale.ROOT, "  %s (x %.5f, y %+.3e)", bead(listened[j]), finalPos[j][0], finalPos[j][1]);
        }
        out.println();
        printEnergies(out, "joules", e0, e1, restEnergy, "total minus the straight string at rest");
        double kept = (e1[2] - restEnergy) / (e0[2] - restEnergy);
        out.printf(Locale.ROOT, "    vibration energy left after %s s: %.2f %% (air friction alone: "
                + "exp(-f t / M) = %.2f %%)%n", num(SECONDS), 100 * kept,
                100 * Math.exp(-AIR_FRICTION * SECONDS / BEAD_MASS));

        int pitchColumn = -1;
        for (int j = 0; j < listened.length; j++) {
            if (listened[j] == PITCH_BEAD) {
                pitchColumn = j;
            }
        }
        double measured = fundamentalFromZeroCrossings(ys[pitchColumn], STRING_RATE);
        double ideal = Math.sqrt(tension / (BEAD_MASS / BEAD_SPACING)) / (2 * stringLength());
        Result r = new Result(dir, measured, theory);
        out.printf(Locale.ROOT, "  fundamental, from the zero crossings of %s: measured %.3f Hz%n",
                bead(PITCH_BEAD), measured);
        out.printf(Locale.ROOT, "  fundamental, theory 2 (1 - cos w) M = 4 Kt sin^2(pi / (2 (N + 1))), "
                + "Kt = K (1 - l0/d): %.3f Hz%n", theory);
        out.printf(Locale.ROOT, "  error: %+.2f cents (tolerance %s cents); an ideal continuous string with the "
                + "same tension and mass would give %.3f Hz%n", r.errorCents, num(PITCH_TOLERANCE_CENTS), ideal);

        String[] names = new String[listened.length];
        StringBuilder header = new StringBuilder("t_s");
        for (int j = 0; j < listened.length; j++) {
            names[j] = bead(listened[j]);
            header.append(',').append(names[j]).append("_y_m");
        }
        writeCsv(r.stringCsv, header.toString(), t, ys, 8);

        // The first 20 ms, in milliseconds and millimetres.
        int shown = (int) Math.round(0.020 * STRING_RATE);
        double[] tMs = new double[shown + 1];
        for (int s = 0; s <= shown; s++) {
            tMs[s] = t[s] * 1e3;
        }
        LineChart plot = new LineChart(String.format(Locale.ROOT,
                "Plucked string: sideways displacement of three beads (first 20 ms of %s s)", num(SECONDS)),
                "time (ms)", "displacement y (mm)");
        for (int j = 0; j < listened.length; j++) {
            double[] mm = new double[shown + 1];
            for (int s = 0; s <= shown; s++) {
                mm[s] = ys[j][s] * 1e3;
            }
            plot.series(names[j] + " (" + num(listened[j] * BEAD_SPACING * 100) + " cm from the left end)", tMs, mm);
        }
        plot.save(r.stringPng.toFile(), PLOT_WIDTH, PLOT_HEIGHT);

        LineChart shape = new LineChart("Plucked string: its shape during the first half period",
                "position along the string x (cm)", "displacement y (mm)");
        for (int k = 0; k < shapes; k++) {
            double[] cm = new double[n + 2];
            double[] mm = new double[n + 2];
            for (int i = 0; i < n + 2; i++) {
                cm[i] = shapeX[k][i] * 100;
                mm[i] = shapeY[k][i] * 1e3;
            }
            shape.series(String.format(Locale.ROOT, "t = %.2f ms (%d/8 period)",
                    shapeStep[k] * 1e3 / STRING_RATE, k), cm, mm);
        }
        shape.markers(true).save(r.stringShapePng.toFile(), PLOT_WIDTH, PLOT_HEIGHT);
        out.printf(Locale.ROOT, "  wrote string.csv (t_s then the y of %s, in m, at every step), string.png "
                + "and string-shape.png%n", String.join(", ", names));
        return r;
    }

    // ================================================================ measuring

    /**
     * Estimates the fundamental frequency of a signal from its upward zero crossings (located by
     * linear interpolation between samples): the number of whole periods between the first and
     * the last crossing, divided by the time between them.
     *
     * @param signal samples, taken at {@code rate} per second
     * @param rate   samples per second
     * @return the frequency in Hz, or NaN if there are fewer than two upward crossings
     */
    public static double fundamentalFromZeroCrossings(double[] signal, double rate) {
        double first = Double.NaN;
        double last = Double.NaN;
        int count = 0;
        for (int i = 1; i < signal.length; i++) {
            double a = signal[i - 1];
            double b = signal[i];
            if (a < 0 && b >= 0) {
                double at = (i - 1) + a / (a - b);
                if (count == 0) {
                    first = at;
                }
                last = at;
                count++;
            }
        }
        if (count < 2) {
            return Double.NaN;
        }
        return (count - 1) * rate / (last - first);
    }

    /** @return the interval from {@code reference} to {@code f} in cents (1200 per octave). */
    public static double cents(double f, double reference) {
        return 1200 * Math.log(f / reference) / Math.log(2);
    }

    private static double[] energies(PhysicalModel mdl) {
        return new double[] {mdl.getKineticEnergy(), mdl.getPotentialEnergy(), mdl.getTotalEnergy()};
    }

    private static void printEnergies(PrintStream out, String unit, double[] start, double[] end, double rest,
                                      String restMeaning) {
        out.printf(Locale.ROOT, "  energy (%s)%n", unit);
        out.printf(Locale.ROOT, "    %-22s %14s %14s%n", "", "start", "end");
        out.printf(Locale.ROOT, "    %-22s %14.6e %14.6e%n", "kinetic", start[0], end[0]);
        out.printf(Locale.ROOT, "    %-22s %14.6e %14.6e%n", "potential", start[1], end[1]);
        out.printf(Locale.ROOT, "    %-22s %14.6e %14.6e%n", "total", start[2], end[2]);
        out.printf(Locale.ROOT, "    %-22s %14.6e %14.6e   (%s)%n", "vibration", start[2] - rest, end[2] - rest,
                restMeaning);
    }

    private static void requireFinite(String model, String what, double[][] series) {
        for (double[] s : series) {
            for (int i = 0; i < s.length; i++) {
                if (!Double.isFinite(s[i])) {
                    throw new DemoFailure(model + " diverged: a position of the " + what + " became " + s[i]
                            + " at step " + i);
                }
            }
        }
    }

    // ================================================================ output

    /** Writes a CSV: the time with {@code timeDecimals} decimals, then each column as {@code %.7e}. */
    private static void writeCsv(Path file, String header, double[] t, double[][] columns, int timeDecimals)
            throws IOException {
        try (BufferedWriter w = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            w.write(header);
            w.write('\n');
            StringBuilder line = new StringBuilder(96);
            for (int i = 0; i < t.length; i++) {
                line.setLength(0);
                CsvNumbers.fixed(line, t[i], timeDecimals);
                for (double[] c : columns) {
                    CsvNumbers.scientific(line.append(','), c[i], 7);
                }
                line.append('\n');
                w.append(line);
            }
        }
    }

    /** A short decimal rendering of a parameter value: 0.0002, 54000, 1.5. */
    private static String num(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        String s = new java.math.BigDecimal(Double.toString(v)).stripTrailingZeros().toPlainString();
        return s.length() <= 12 ? s : String.format(Locale.ROOT, "%.6g", v);
    }

    /** Prints a progress line at most once per second of wall-clock time while a long run goes on. */
    private static final class Progress {
        private final PrintStream out;
        private final String what;
        private final long total;
        private final long start = System.nanoTime();
        private long lastPrint = start;

        Progress(PrintStream out, String what, long total) {
            this.out = out;
            this.what = what;
            this.total = total;
        }

        void update(long done) {
            long now = System.nanoTime();
            if (now - lastPrint >= 1_000_000_000L) {
                out.printf(Locale.ROOT, "  ... %s: %,d of %,d steps (%.0f %%), %.1f s%n", what, done, total,
                        100.0 * done / total, (now - start) * 1e-9);
                lastPrint = now;
            }
        }

        double elapsed() {
            return (System.nanoTime() - start) * 1e-9;
        }
    }
}
