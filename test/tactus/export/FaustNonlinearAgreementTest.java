package tactus.export;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static tactus.export.FaustAgreementTest.check;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Supplier;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.faust.FaustToolchain;
import tactus.export.FaustAgreementTest.Point;
import tactus.export.FaustAgreementTest.Strike;

/**
 * mi.lib's six nonlinear interactions exported through mi.lib's own functions, compiled with {@code faust -double}
 * and {@code g++}, rendered over 4,096 samples and compared with Tactus stepping the same model, to the linear
 * modules' tolerance ({@link FaustAgreementTest#TOLERANCE}, relative).
 */
@Timeout(170)
class FaustNonlinearAgreementTest {
    @TempDir
    static Path dir;

    @BeforeAll
    static void tools() {
        FaustToolchain.requireTools();
        FaustAgreementTest.dir = dir; // check() compiles there
    }

    /** A 1-D string of n masses between two grounds; {@code link} adds link i between masses a and b. */
    interface LinkMaker {
        void add(PhysicalModel m, String name, String a, String b);
    }

    static PhysicalModel string(int n, LinkMaker link) {
        PhysicalModel m = new PhysicalModel(44100);
        m.addGround1D("g0", new Vect3D(0, 0, 0));
        for (int i = 1; i <= n; i++) {
            m.addMass1D("m" + i, 1, new Vect3D(i, 0, 0), new Vect3D());
        }
        m.addGround1D("g1", new Vect3D(n + 1, 0, 0));
        for (int i = 0; i <= n; i++) {
            link.add(m, "s" + i, i == 0 ? "g0" : "m" + i, i == n ? "g1" : "m" + (i + 1));
        }
        return m;
    }

    private static void agree(String name, Supplier<PhysicalModel> model, List<Point> pts, List<Strike> st,
                              String function) throws IOException {
        String dsp = check(name, model.get(), model.get(), pts, st, null);
        assertTrue(dsp.contains("mi." + function + "("), name + " is written with mi." + function);
    }

    @Test
    void aStringOfQuadraticSprings() throws IOException {
        agree("nlSpringDamper2", () -> init(string(20, (m, n, a, b) -> m.addQuadraticSpringDamper1D(n, 0, 0.1,
                        0.0005, 0.3, a, b))),
                List.of(new Point("m12", 2, 1), new Point("m4", 2, 1)), List.of(new Strike("m7", 2, 0.3)),
                "nlSpringDamper2");
    }

    @Test
    void aStringOfCubicSpringsWithRestLengths() throws IOException {
        agree("nlSpringDamper3", () -> init(string(20, (m, n, a, b) -> m.addCubicSpringDamper1D(n, 0.01, 0.1,
                        0.0005, 0.4, a, b))),
                List.of(new Point("m12", 2, 1), new Point("m4", 2, 1)), List.of(new Strike("m7", 2, 0.5)),
                "nlSpringDamper3");
    }

    /** b = sqrt(0.3 - 0.05) / 0.5 = 1: a strike of 0.2 keeps the string in the law's cubic part. */
    @Test
    void aStringOfClippedSprings() throws IOException {
        agree("nlSpringDamperClipped", () -> init(string(12, (m, n, a, b) -> m.addClippedSpringDamper1D(n, 0, 0.05,
                        0.0005, 0.5, 0.3, a, b))),
                List.of(new Point("m6", 2, 1), new Point("m3", 2, 1)), List.of(new Strike("m5", 2, 0.2)),
                "nlSpringDamperClipped");
    }

    /**
     * One mass on a clipped spring, struck hard enough to swing past the clipping point b = 1 and back. (A string
     * struck that hard is chaotic: mi.lib's force jumps at b, and after 4,096 samples Faust and Tactus differ by
     * 0.96 relative, as any two implementations would.)
     */
    @Test
    void aMassSwingingThroughTheClip() throws IOException {
        PhysicalModel probe = swing();
        probe.triggerForceImpulse("m", 0, 0, 0.6);
        double most = 0;
        for (int n = 0; n < 4096; n++) {
            probe.computeStep();
            most = Math.max(most, Math.abs(probe.getMatPosition("m").z));
        }
        assertTrue(most > 1.2, "the swing crosses b = 1: " + most);
        agree("nlSpringDamperClippedSwing", FaustNonlinearAgreementTest::swing, List.of(new Point("m", 2, 1)),
                List.of(new Strike("m", 2, 0.6)), "nlSpringDamperClipped");
    }

    static PhysicalModel swing() {
        PhysicalModel m = new PhysicalModel(44100);
        m.addGround1D("g", new Vect3D(0, 0, 0));
        m.addMass1D("m", 1, new Vect3D(0, 0, 0), new Vect3D());
        m.addClippedSpringDamper1D("s", 0, 0.05, 0.0005, 0.5, 0.3, "m", "g");
        return init(m);
    }

    /** A heavy plectrum crosses a string mass through a pluck's range: it pushes, tips past, and lets go. */
    @Test
    void aPlectrumPlucksAString() throws IOException {
        agree("nlPluck", () -> {
            PhysicalModel m = string(16, (mm, n, a, b) -> mm.addSpringDamper1D(n, 0, 0.1, 0.0003, a, b));
            m.addMass1D("plectrum", 1e4, new Vect3D(6, 1, -0.3), new Vect3D(0, 0, 0.0002 * 44100));
            m.addPluck1D("pluck", 0, 0.05, 0.0002, 0.2, "plectrum", "m6");
            return init(m);
        }, List.of(new Point("m6", 2, 1), new Point("m11", 2, 1)), List.of(), "nlPluck");
    }

    /** A heavy bow drawn at a constant speed across a string mass: stick-slip, in both of mi.lib's profiles. */
    @Test
    void aBowedString() throws IOException {
        for (int profile = 0; profile <= 1; profile++) {
            int p = profile;
            agree("nlBow" + p, () -> {
                PhysicalModel m = string(16, (mm, n, a, b) -> mm.addSpringDamper1D(n, 0, 0.1, 0.0003, a, b));
                m.addMass1D("bow", 1e4, new Vect3D(5, 1, 0), new Vect3D(0, 0, 0.002 * 44100));
                m.addBow1D("friction", 0.3, 0.004, p, "bow", "m5");
                return init(m);
            }, List.of(new Point("m5", 2, 1), new Point("m10", 2, 1)), List.of(), "nlBow");
        }
    }

    /** A hammer strikes a bar from above through a clipped contact; the bar (below) is mass 1, as mi.lib has it. */
    @Test
    void aHammerOnABarThroughAClippedContact() throws IOException {
        agree("nlCollisionClipped", () -> {
            PhysicalModel m = new PhysicalModel(44100);
            m.addGround1D("g", new Vect3D(0, 0, 0));
            m.addOsc1D("bar", 1, 0.01, 0.0001, new Vect3D(0, 0, 1), new Vect3D());
            m.addMass1D("hammer", 0.5, new Vect3D(0, 0, 1.6), new Vect3D(0, 0, -400));
            m.addSpringDamper1D("hold", 1, 0.02, 0.0001, "bar", "g");
            m.addClippedContact1D("hit", 0.1, 0.02, 0.001, 2, 0.1, "bar", "hammer");
            return init(m);
        }, List.of(new Point("bar", 2, 1), new Point("hammer", 2, 1)), List.of(), "nlCollisionClipped");
    }

    /** A 3-D string of n Mass3D, one displaced, whose links {@code link} adds (rest length 0.8, spacing 1). */
    static PhysicalModel string3D(int n, LinkMaker link) {
        PhysicalModel m = new PhysicalModel(44100);
        m.addGround3D("g0", new Vect3D(0, 0, 0));
        for (int i = 1; i <= n; i++) {
            m.addMass3D("m" + i, 1, new Vect3D(i, i == n / 3 ? 0.2 : 0, 0), new Vect3D());
        }
        m.addGround3D("g1", new Vect3D(n + 1, 0, 0));
        for (int i = 0; i <= n; i++) {
            link.add(m, "s" + i, i == 0 ? "g0" : "m" + i, i == n ? "g1" : "m" + (i + 1));
        }
        return m;
    }

    private static final List<Point> STRING3D = List.of(new Point("m10", 1, 10), new Point("m10", 0, 10),
            new Point("m4", 2, 10));

    /** The 3-D forms: mi.lib's own function applied along the distance, in the explicit scheme. */
    @Test
    void threeDStringsOfEachSpringLaw() throws IOException {
        agree("nlSpringDamper2-3d", () -> init(string3D(16, (m, n, a, b) -> m.addQuadraticSpringDamper3D(n, 0.8, 0.1,
                0.0003, 0.3, a, b))), STRING3D, List.of(new Strike("m6", 2, 0.2)), "nlSpringDamper2");
        agree("nlSpringDamper3-3d", () -> init(string3D(16, (m, n, a, b) -> m.addCubicSpringDamper3D(n, 0.8, 0.1,
                0.0003, 0.5, a, b))), STRING3D, List.of(new Strike("m6", 2, 0.2)), "nlSpringDamper3");
        agree("nlSpringDamperClipped-3d", () -> init(string3D(16, (m, n, a, b) -> m.addClippedSpringDamper3D(n, 0.8,
                0.05, 0.0003, 0.5, 0.3, a, b))), STRING3D, List.of(new Strike("m6", 2, 0.1)), "nlSpringDamperClipped");
    }

    /** A plectrum (heavy Mass3D) drawn across a 3-D string mass by a Pluck3D, rest length 0.3, scale 0.2. */
    @Test
    void aThreeDPluck() throws IOException {
        agree("nlPluck-3d", () -> {
            PhysicalModel m = string3D(12, (mm, n, a, b) -> mm.addSpringDamper3D(n, 0.8, 0.1, 0.0003, a, b));
            m.addMass3D("plectrum", 1e4, new Vect3D(5, -0.5, 0.05), new Vect3D(0, 0.001 * 44100, 0));
            m.addPluck3D("pluck", 0.3, 0.05, 0.0002, 0.2, "plectrum", "m5");
            return init(m);
        }, List.of(new Point("m5", 1, 10), new Point("m8", 1, 10)), List.of(), "nlPluck");
    }

    /** A heavy Mass3D bow drawn across a 3-D string mass by a Bow3D (its law on the relative velocity vector). */
    @Test
    void aThreeDBow() throws IOException {
        String dsp = check("bow3d", bowed3D(), bowed3D(), List.of(new Point("m5", 1, 10), new Point("m8", 1, 10)),
                List.of(), null);
        assertTrue(dsp.contains("bow3("), "Bow3D is written with its law on the relative velocity");
    }

    static PhysicalModel bowed3D() {
        PhysicalModel m = string3D(12, (mm, n, a, b) -> mm.addSpringDamper3D(n, 0.8, 0.1, 0.0003, a, b));
        m.addMass3D("bow", 1e4, new Vect3D(5, 0, 0.3), new Vect3D(0, 0.002 * 44100, 0.0005 * 44100));
        m.addBow3D("friction", 0.3, 0.004, 0, "bow", "m5");
        return init(m);
    }

    /** A hammer (Mass3D) thrown at a 3-D bar through a ClippedContact3D, threshold 0.2. */
    @Test
    void aThreeDClippedContact() throws IOException {
        agree("nlCollisionClipped-3d", () -> {
            PhysicalModel m = new PhysicalModel(44100);
            m.addOsc3D("bar", 1, 0.01, 0.0001, new Vect3D(0, 0, 1), new Vect3D());
            m.addMass3D("hammer", 0.5, new Vect3D(0.05, 0.02, 1.6), new Vect3D(0, 0, -400));
            m.addClippedContact3D("hit", 0.2, 0.02, 0.001, 2, 0.1, "bar", "hammer");
            return init(m);
        }, List.of(new Point("bar", 2, 1), new Point("hammer", 2, 1), new Point("bar", 0, 10)), List.of(),
                "nlCollisionClipped");
    }

    private static PhysicalModel init(PhysicalModel m) {
        m.init();
        return m;
    }
}
