package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.StabilityReport;
import tactus.Vect3D;

/**
 * Scenes of mi.lib's nonlinear interactions: a bowed mass sticks and slips, a pluck pushes a string and lets it go
 * past its scale, a clipped contact throws a hammer back, and the stability check bounds what it can.
 */
class NonlinearScenesTest {
    /** A mass on a spring to the ground, a heavy bow drawn at {@code speed} per step along z through a Bow1D. */
    private static PhysicalModel bowed(double speed) {
        PhysicalModel m = new PhysicalModel(1000);
        m.addGround1D("g", new Vect3D(0, 0, 0));
        m.addMass1D("m", 1, new Vect3D(0, 0, 0), new Vect3D());
        m.addSpringDamper1D("s", 0, 0.01, 0.0001, "m", "g");
        m.addMass1D("bow", 1e6, new Vect3D(1, 0, 0), new Vect3D(0, 0, speed * 1000));
        m.addBow1D("friction", 0.5, 0.01, 0, "bow", "m");
        m.init();
        return m;
    }

    /** @return {stick fraction, slip fraction, sign changes of the mass's velocity} over n steps */
    private static double[] stickSlip(double speed, int n) {
        PhysicalModel m = bowed(speed);
        double tip = 0.01 / 3;
        int stick = 0, slip = 0, turns = 0;
        double prevZ = 0, prevBow = m.getMatPosition("bow").z, prevV = 0;
        for (int i = 0; i < n; i++) {
            m.computeStep();
            double z = m.getMatPosition("m").z, bz = m.getMatPosition("bow").z;
            double v = z - prevZ, rel = (bz - prevBow) - v;
            if (i > 100) {
                if (Math.abs(rel) < tip) {
                    stick++;
                } else {
                    slip++;
                }
                if (v * prevV < 0) {
                    turns++;
                }
            }
            prevV = v;
            prevZ = z;
            prevBow = bz;
        }
        return new double[] {stick / (double) (n - 101), slip / (double) (n - 101), turns};
    }

    @Test
    void aBowedMassSticksAndSlips() {
        // drawn between the friction's peak (scale / 3) and its scale, where the friction falls as sliding speeds up
        double[] s = stickSlip(0.006, 20000);
        assertTrue(s[0] > 0.2, "it sticks (moves with the bow) a good part of the time: " + s[0]);
        assertTrue(s[1] > 0.05, "and slips back: " + s[1]);
        assertTrue(s[2] >= 10, "over and over (velocity turns): " + s[2]);
        // drawn faster than the friction's scale, the bow never grips: no stick
        double[] fast = stickSlip(0.05, 5000);
        assertTrue(fast[0] < 0.01, "a bow drawn beyond its scale slides: " + fast[0]);
    }

    @Test
    void aPluckPushesThenLetsGoPastItsScale() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addGround1D("g", new Vect3D(0, 0, 0));
        m.addMass1D("string", 1, new Vect3D(0, 0, 0), new Vect3D());
        m.addSpringDamper1D("s", 0, 0.01, 0, "string", "g");
        // the plectrum starts 0.3 below, beyond the scale 0.2, and rises at 0.0005 per step
        m.addMass1D("plectrum", 1e6, new Vect3D(1, 0, -0.3), new Vect3D(0, 0, 0.5));
        m.addPluck1D("pluck", 0, 0.02, 0, 0.2, "plectrum", "string");
        m.init();
        double pushed = 0, released = Double.NaN, afterMin = 0, afterMax = 0;
        for (int i = 0; i < 4000; i++) {
            m.computeStep();
            double s = m.getMatPosition("string").z, e = m.getMatPosition("plectrum").z - s;
            if (Double.isNaN(released)) {
                pushed = Math.max(pushed, s);
                if (e > 0.2) {
                    released = i;
                }
            } else if (e > 0.2) {
                afterMin = Math.min(afterMin, s);
                afterMax = Math.max(afterMax, s);
            }
        }
        assertFalse(Double.isNaN(released), "the plectrum passes the string");
        assertTrue(pushed > 0.02, "before it lets go, the pluck pushes the string up: " + pushed);
        assertTrue(afterMin < -0.02 && afterMax > 0.02, "once released the string rings freely on both sides: "
                + afterMin + " .. " + afterMax);
    }

    @Test
    void aClippedContactThrowsAHammerBack() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addGround1D("floor", new Vect3D(0, 0, 0));
        m.addMass1D("hammer", 1, new Vect3D(0, 0, 0.5), new Vect3D(0, 0, -5));
        m.addClippedContact1D("hit", 0.1, 0.01, 0, 5, 0.5, "floor", "hammer");
        m.init();
        double lowest = 1;
        for (int i = 0; i < 1000; i++) {
            m.computeStep();
            lowest = Math.min(lowest, m.getMatPosition("hammer").z);
        }
        assertTrue(lowest > 0 && lowest < 0.1, "it enters the threshold without passing the floor: " + lowest);
        assertTrue(m.getMatVelocity("hammer").z > 0, "and flies back up");
    }

    @Test
    void theStabilityCheckBoundsWithTheLargestSlopeTheLawReaches() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addGround1D("g", new Vect3D(0, 0, 0));
        m.addMass1D("m", 1, new Vect3D(0, 0, 0), new Vect3D());
        // linear part 0.1, well within the bound 4, but past mi.lib's clipping point b = sqrt(Kmax - K) / C the
        // cubic's slope K + 3 C b^2 = 17.8 is what the law reaches
        m.addClippedSpringDamper1D("clip", 0, 0.1, 0, 1, 6, "m", "g");
        StabilityReport r = m.getStabilityReport();
        assertFalse(r.isStable(), r.toString());
        assertTrue(r.getCulprit().contains("clip"), r.getCulprit());
        // with Kmax = 1 the slope reaches 0.1 + 3 * 0.9 = 2.8 and the over-damping 0.3 Kmax adds 0.6: stable
        PhysicalModel ok = new PhysicalModel(1000);
        ok.addGround1D("g", new Vect3D(0, 0, 0));
        ok.addMass1D("m", 1, new Vect3D(0, 0, 0), new Vect3D());
        ok.addClippedSpringDamper1D("clip", 0, 0.1, 0, 1, 1, "m", "g");
        assertTrue(ok.getStabilityReport().isStable(), ok.getStabilityReport().toString());
    }
}
