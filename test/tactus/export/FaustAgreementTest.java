package tactus.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;
import tactus.faust.FaustToolchain;

/**
 * Exports models to Faust, compiles them with the Debian {@code faust} (-double) and {@code g++}, renders 4,096
 * samples and compares them with Tactus stepping the same model and reading the same outputs: they must agree to
 * 1e-9 relative (the largest difference over the largest magnitude of the signal). Without faust or g++ the tests
 * fail and say what to install.
 */
@Timeout(170)
class FaustAgreementTest {
    static final int N = 4096;
    static final double TOLERANCE = 1e-9;

    @TempDir
    static Path dir;

    @BeforeAll
    static void tools() {
        FaustToolchain.requireTools();
    }

    /** A listening point: mass, axis, gain. */
    static final class Point {
        final String mass;
        final int axis;
        final double gain;

        Point(String mass, int axis, double gain) {
            this.mass = mass;
            this.axis = axis;
            this.gain = gain;
        }
    }

    /** A force impulse on input {@code input} at sample 0: mass, axis, force in the model's units. */
    static final class Strike {
        final String mass;
        final int axis;
        final double force;

        Strike(String mass, int axis, double force) {
            this.mass = mass;
            this.axis = axis;
            this.force = force;
        }
    }

    static FaustExportOptions options(List<Point> points, List<Strike> strikes) {
        FaustExportOptions o = new FaustExportOptions();
        for (Point p : points) {
            o.listen(p.mass, p.axis, p.gain);
        }
        for (Strike s : strikes) {
            o.forceInput(s.mass, s.axis);
        }
        return o;
    }

    /** Tactus's own rendering: the strikes before the first step, then one step and one reading per sample. */
    static double[][] tactus(PhysicalModel m, List<Point> points, List<Strike> strikes, int n) {
        double[] origin = new double[points.size()];
        for (int i = 0; i < origin.length; i++) {
            origin[i] = coord(m.getMatPosition(points.get(i).mass), points.get(i).axis);
        }
        for (Strike s : strikes) {
            m.triggerForceImpulse(s.mass, s.axis == 0 ? s.force : 0, s.axis == 1 ? s.force : 0,
                    s.axis == 2 ? s.force : 0);
        }
        double[][] r = new double[points.size()][n];
        for (int k = 0; k < n; k++) {
            m.computeStep();
            for (int i = 0; i < origin.length; i++) {
                Point p = points.get(i);
                r[i][k] = (coord(m.getMatPosition(p.mass), p.axis) - origin[i]) * p.gain;
            }
        }
        return r;
    }

    static double coord(Vect3D v, int axis) {
        return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
    }

    static List<String> strikeArgs(List<Strike> strikes) {
        List<String> a = new ArrayList<>();
        for (int i = 0; i < strikes.size(); i++) {
            a.addAll(List.of("-in", Integer.toString(i), "0", Double.toString(strikes.get(i).force)));
        }
        return a;
    }

    /** @return max |a - b| over max |a|, over every output */
    static double relative(double[][] tactus, double[][] faust) {
        double diff = 0;
        double mag = 0;
        for (int c = 0; c < tactus.length; c++) {
            for (int k = 0; k < tactus[c].length; k++) {
                diff = Math.max(diff, Math.abs(tactus[c][k] - faust[c][k]));
                mag = Math.max(mag, Math.abs(tactus[c][k]));
            }
        }
        assertTrue(mag > 0, "the Tactus signal is silent: nothing to compare");
        return diff / mag;
    }

    /** Exports, compiles (-double), renders and compares; @return the Faust source. */
    static String check(String name, PhysicalModel exported, PhysicalModel reference, List<Point> points,
                        List<Strike> strikes, FaustExportOptions extra) throws IOException {
        FaustExportOptions o = extra != null ? extra : options(points, strikes);
        String dsp = FaustExporter.toDsp(exported, o);
        FaustToolchain.Program p = FaustToolchain.compile(dsp, dir, name, true, "-O1", 120);
        double[][] faust = FaustToolchain.render(p, N, strikeArgs(strikes), 60);
        double[][] ours = tactus(reference, points, strikes, N);
        assertEquals(points.size(), faust.length, name + ": outputs");
        double rel = relative(ours, faust);
        System.out.printf("%s: relative difference %.3g over %d samples (faust %d ms, g++ %d ms)%n", name, rel, N,
                p.faustMillis, p.gccMillis);
        assertTrue(rel < TOLERANCE, name + ": Faust and Tactus differ by " + rel + " (relative) > " + TOLERANCE
                + "\n" + dsp.substring(0, Math.min(dsp.length(), 3000)));
        return dsp;
    }

    // ------------------------------------------------------------------------------------------- models

    static PhysicalModel string1D(int masses) {
        PhysicalModel m = new PhysicalModel(44100);
        m.addGround1D("g0", new Vect3D(0, 0, 0));
        for (int i = 1; i <= masses; i++) {
            m.addMass1D("m" + i, 1, new Vect3D(i, 0, 0), new Vect3D());
        }
        m.addGround1D("g1", new Vect3D(masses + 1, 0, 0));
        m.createLinkSubset("string");
        for (int i = 0; i <= masses; i++) {
            String a = i == 0 ? "g0" : "m" + i;
            String b = i == masses ? "g1" : "m" + (i + 1);
            m.addSpringDamper1D("s" + i, 0, 0.2, 0.0005, a, b);
            m.addLinkToSubset("s" + i, "string");
        }
        m.init();
        return m;
    }

    @Test
    void a1DStringStruckByAnImpulse() throws IOException {
        List<Point> pts = List.of(new Point("m20", 2, 100), new Point("m5", 2, 1));
        List<Strike> st = List.of(new Strike("m7", 2, 1.0));
        String dsp = check("string1d", string1D(30), string1D(30), pts, st, null);
        assertTrue(dsp.contains("mi.mass(") && dsp.contains("mi.springDamper(") && dsp.contains("mi.ground("),
                "a 1-D string is written with mi.lib's primitives");
    }

    @Test
    void a1DStringExportedWhileRinging() throws IOException {
        PhysicalModel a = string1D(30);
        PhysicalModel b = string1D(30);
        for (PhysicalModel m : new PhysicalModel[] {a, b}) {
            m.setFriction(0.0002);
            m.setMatPosition("m12", new Vect3D(12, 0, 0.3));
            m.setMatVelocity("m3", new Vect3D(0, 0, 500));
            m.triggerForceImpulse("m20", 0, 0, -0.5);
            m.computeNSteps(37);
        }
        check("ringing", a, b, List.of(new Point("m12", 2, 1), new Point("m25", 2, 1)), List.of(), null);
    }

    @Test
    void aSliderKeepsItsControl() throws IOException {
        List<Point> pts = List.of(new Point("m20", 2, 100));
        List<Strike> st = List.of(new Strike("m7", 2, 1.0));
        FaustExportOptions o = options(pts, st).slider("stiffness", FaustExportOptions.STIFFNESS, "string");
        String dsp = FaustExporter.toDsp(string1D(30), o);
        assertTrue(dsp.contains("hslider(\"stiffness\", 0.2, 0.0, 0.4"), dsp);
        FaustToolchain.Program p = FaustToolchain.compile(dsp, dir, "slider", true, "-O1", 120);
        List<String> args = new ArrayList<>(strikeArgs(st));
        args.addAll(List.of("-set", "stiffness", "0.3"));
        double[][] faust = FaustToolchain.render(p, N, args, 60);
        PhysicalModel ref = string1D(30);
        ref.changeStiffnessParamOfSubset(0.3, "string");
        double rel = relative(tactus(ref, pts, st, N), faust);
        System.out.printf("slider at 0.3: relative difference %.3g%n", rel);
        assertTrue(rel < TOLERANCE, "the slider set to 0.3 plays the model with stiffness 0.3: " + rel);
    }

    static PhysicalModel plate(int n) {
        return tactus.faust.FaustCost.plate(n);
    }

    @Test
    void thePapersMetalPlate() throws IOException {
        List<Point> pts = List.of(new Point("p3_5", 2, 3), new Point("p2_6", 2, 3));
        List<Strike> st = List.of(new Strike("p1_1", 2, 0.3));
        String dsp = check("plate", plate(8), plate(8), pts, st, null);
        assertTrue(dsp.contains("mi.oscil("), "Osc1D is written as mi.oscil");
    }

    static PhysicalModel oscillatorBank() {
        PhysicalModel m = new PhysicalModel(44100, paramSystem.REAL_UNITS);
        for (int i = 0; i < 6; i++) {
            double f = 220 * (i + 1) * 1.01;
            double mass = 0.001 * (1 + i);
            double k = mass * Math.pow(2 * Math.PI * f, 2);
            m.addOsc1D("o" + i, mass, k, 0.0005 * (i + 1), new Vect3D(i, 0, 0.01 * i),
                    new Vect3D(0, 0, 0.3 / (i + 1)));
        }
        m.setFriction(0.0001);
        m.setGravity(9.81);
        m.init();
        return m;
    }

    @Test
    void anOscillatorBankInRealUnits() throws IOException {
        List<Point> pts = List.of(new Point("o0", 2, 1), new Point("o3", 2, 1), new Point("o5", 2, 1));
        check("bank", oscillatorBank(), oscillatorBank(), pts, List.of(new Strike("o2", 2, 2.0)), null);
    }

    static PhysicalModel string3D(int masses) {
        PhysicalModel m = new PhysicalModel(44100);
        m.addGround3D("g0", new Vect3D(0, 0, 0));
        for (int i = 1; i <= masses; i++) {
            m.addMass3D("m" + i, 1, new Vect3D(i, i == masses / 3 ? 0.2 : 0, 0), new Vect3D());
        }
        m.addGround3D("g1", new Vect3D(masses + 1, 0, 0));
        for (int i = 0; i <= masses; i++) {
            String a = i == 0 ? "g0" : "m" + i;
            String b = i == masses ? "g1" : "m" + (i + 1);
            m.addSpringDamper3D("s" + i, 0.8, 0.1, 0.0003, a, b);
        }
        m.setFriction(0.00005);
        m.setGravity(1e-7);
        m.init();
        return m;
    }

    @Test
    void a3DString() throws IOException {
        List<Point> pts = List.of(new Point("m10", 1, 10), new Point("m10", 0, 10), new Point("m4", 2, 10));
        String dsp = check("string3d", string3D(20), string3D(20), pts, List.of(new Strike("m6", 2, 0.2)), null);
        assertTrue(dsp.contains("springDamper(") && !dsp.contains("mi.mass("), "a 3-D model is the explicit scheme");
    }

    /**
     * Every form the explicit writer has: each mass kind and each interaction kind, with gravity and friction,
     * vibrating a little around its rest state. The conditional interactions (rope, bubble, contact, plane) stay
     * engaged throughout, with a margin of 0.05 against vibrations of about 1e-3: engaging and letting go again
     * and again, or moving far enough for the distance-based springs to be nonlinear, makes such a coupled model
     * chaotic, and rounding differences then grow tenfold every ~120 steps (measured on a first version: 1e-16
     * at step 5, 1e-9 at step 1,100, 0.5 at 4,096), between any two implementations.
     */
    static PhysicalModel everyKind() {
        PhysicalModel m = new PhysicalModel(44100);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        m.addGround3D("gp", new Vect3D(4, 0, 0.5));
        m.addMass3D("a", 1, new Vect3D(1, 0, 0), new Vect3D(0, 5, 3));
        m.addOsc3D("o", 1, 0.02, 0.0002, new Vect3D(2, 0.1, 0), new Vect3D(0, 0, 5));
        m.addMass2DPlane("p", 0.5, new Vect3D(3, 0, 0.5), new Vect3D(2, 0, 0));
        m.addMass1D("q", 0.7, new Vect3D(3, 1, 0), new Vect3D());
        m.addMass3DSimple("s", 1, new Vect3D(0, 2, 0), new Vect3D(0, 0, 3));
        double ao = Math.sqrt(1 + 0.01);
        double op = Math.sqrt(1 + 0.01 + 0.25);
        double pq = Math.sqrt(1 + 0.25);
        m.addSpring3D("spring", 1, 0.05, "g", "a");
        m.addDamper3D("damper", 0.001, "g", "a");
        m.addSpringDamper3D("sd", ao, 0.03, 0.0003, "a", "o");
        m.addRope3D("rope", op - 0.05, 0.01, 0.0002, "o", "p");
        m.addSpringDamper3D("anchor", 1, 0.05, 0.0002, "p", "gp");
        m.addSpringDamper1D("sd1", 0.5, 0.02, 0.0001, "p", "q");
        m.addBubble3D("bubble", 0.95, 0.05, 0.0005, "a", "g");
        m.addAttractor3D("attractor", 0.1, 1e-5, "o", "q");
        m.addPlaneContact("plane", 0, 0.05, 0.001, 0, 1.05, "a");
        m.addContact3D("contact", pq + 0.05, 0.005, 0.0003, "p", "q");
        m.addSpring3D("hold", 2, 0.02, "s", "g");
        m.setGravity(1e-7);
        m.setFriction(0.00001);
        m.init();
        return m;
    }

    @Test
    void everyExplicitForm() throws IOException {
        List<Point> pts = List.of(new Point("a", 1, 1), new Point("o", 0, 1), new Point("p", 0, 1),
                new Point("q", 2, 1), new Point("s", 2, 1), new Point("a", 2, 1));
        String dsp = check("every", everyKind(), everyKind(), pts, List.of(new Strike("o", 1, 0.01)), null);
        for (String form : new String[] {"spring(", "damper(", "springDamper(", "stretched(", "sd1(", "attractor(",
            "plane(", "contact(", "osc("}) {
            assertTrue(dsp.substring(dsp.indexOf("\nmasses = ")).contains(form), "the program uses " + form);
        }
    }

    /**
     * A bar (an oscillator held by a spring of rest length 1) struck from above by a hammer and from below by a
     * second one, swinging against a stop (a plane contact): every contact of mi.lib's kind, with gravity and air
     * friction. Each hammer strikes once and flies off, so the model is not chaotic (a ball trapped between two
     * contacts is: its rounding differences grow tenfold every ~90 steps, and no two implementations agree).
     */
    static PhysicalModel collision1D() {
        PhysicalModel m = new PhysicalModel(44100);
        m.addGround1D("g", new Vect3D(0, 0, 0));
        m.addOsc1D("bar", 1, 0.01, 0.0001, new Vect3D(0, 0, 1), new Vect3D());
        m.addMass1D("hammer", 0.5, new Vect3D(0, 0, 1.6), new Vect3D(0, 0, -400));
        m.addMass1D("under", 0.2, new Vect3D(0, 0, 0.5), new Vect3D(0, 0, 100));
        m.addSpringDamper1D("hold", 1, 0.02, 0.0001, "bar", "g");
        m.addContact3D("hit", 0.1, 0.05, 0.001, "hammer", "bar");
        m.addContact3D("hitFromBelow", 0.1, 0.05, 0.001, "under", "bar");
        m.addPlaneContact("stop", 0.0, 0.1, 0.002, 2, 0.97, "bar");
        m.setGravity(2e-7);
        m.setFriction(0.00001);
        m.init();
        return m;
    }

    @Test
    void a1DModelWithCollisions() throws IOException {
        List<Point> pts = List.of(new Point("bar", 2, 1), new Point("hammer", 2, 1), new Point("under", 2, 1));
        PhysicalModel ref = collision1D();
        String dsp = check("collision", collision1D(), ref, pts, List.of(), null);
        assertTrue(dsp.contains("mi.collision("), "1-D contacts are written as mi.collision");
    }

    /**
     * Faust's default single precision: the same exported string and plate, compiled without -double, over one
     * second. Prints how far they drift and after how many samples the difference first exceeds 1e-3 of the
     * signal's largest magnitude (figures in docs/faust.md). Asserts only what single precision must show: a
     * difference far above double's rounding, yet a sound that still follows the model over the first 4,096 samples.
     */
    @Test
    void singlePrecisionDrift() throws IOException {
        int n = 44100;
        List<Strike> st = List.of(new Strike("m7", 2, 1.0));
        List<Point> pts = List.of(new Point("m20", 2, 100));
        drift("string-float", string1D(30), string1D(30), pts, st, n);
        drift("plate-float", plate(8), plate(8), List.of(new Point("p3_5", 2, 3)),
                List.of(new Strike("p1_1", 2, 0.3)), n);
    }

    private static void drift(String name, PhysicalModel exported, PhysicalModel reference, List<Point> pts,
                              List<Strike> st, int n) throws IOException {
        String dsp = FaustExporter.toDsp(exported, options(pts, st));
        FaustToolchain.Program p = FaustToolchain.compile(dsp, dir, name, false, "-O1", 120);
        double[][] faust = FaustToolchain.render(p, n, strikeArgs(st), 60);
        double[][] ours = tactus(reference, pts, st, n);
        double mag = 0;
        for (double v : ours[0]) {
            mag = Math.max(mag, Math.abs(v));
        }
        int firstOver = -1;
        double at4096 = 0;
        double atEnd = 0;
        for (int k = 0; k < n; k++) {
            double d = Math.abs(ours[0][k] - faust[0][k]) / mag;
            atEnd = Math.max(atEnd, d);
            if (k < N) {
                at4096 = atEnd;
            }
            if (firstOver < 0 && d > 1e-3) {
                firstOver = k;
            }
        }
        System.out.printf("%s (single precision): relative difference %.3g over %d samples, %.3g over %d; first above"
                + " 1e-3 at sample %d%n", name, at4096, N, atEnd, n, firstOver);
        assertTrue(at4096 > 1e3 * TOLERANCE, name + ": single precision should differ well above double's rounding, "
                + "got " + at4096);
        assertTrue(at4096 < 0.5, name + ": single precision should still follow the model over " + N + " samples, "
                + "got " + at4096);
    }
}
