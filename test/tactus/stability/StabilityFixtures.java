package tactus.stability;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Map;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Test helper (not a test class) shared by the hard-case scenes: state checks, console capture and the
 * energy functions used as bounds. Everything is read through the public facade.
 *
 * <h2>Energies used as bounds (all in algorithmic, per-step units)</h2>
 * For a linear network with mass matrix M, stiffness K and damping Z (symmetric, Z &ge; 0) the scheme is
 * {@code M (X+ - 2X + X-) = -K X - Z (X - X-)}. With {@code v = X - X-} the quantity
 * <pre>  G = ½ vᵀ (M - Z/2) v + ½ Xᵀ K X-  </pre>
 * obeys {@code G+ - G = -¼ (v+ + v)ᵀ Z (v+ + v) &le; 0} exactly (multiply the scheme by {@code X+ - X-}).
 * It is a norm of the state iff {@code M - K/4 - Z/2 > 0}, that is iff {@code λmax(M⁻¹(K + 2Z)) < 4}: the
 * analyser's criterion, for any damping, proportional or not (see docs/stability.md). Without damping G is
 * the scheme's conserved discrete energy {@code ½ M v² + ½ K e(n) e(n-1)}.
 *
 * <p>The facade's {@link PhysicalModel#getTotalEnergy()} is the naive energy {@code ½ M v² + ½ K e²}. Mode by
 * mode (stiffness per unit mass k &le; λ) the ratio naive / G lies in
 * {@code [1 / (1 + √k/2), 1 / (1 - √k/2)]}, so while G does not grow the naive energy can exceed its initial
 * value by at most {@link #naiveEnergyFactor(double)} = {@code (1 + √λ/2) / (1 - √λ/2)}: 1.4 at λ = 0.1, 3 at
 * λ = 1, 400 at λ = 3.96. That is the documented "bounded energy" factor for linear and near-linear scenes.
 */
final class StabilityFixtures {
    private StabilityFixtures() {
    }

    /** Bound on naive energy / its initial value for a linear network whose G does not grow (class comment). */
    static double naiveEnergyFactor(double lambda) {
        double h = Math.sqrt(lambda) / 2;
        return (1 + h) / (1 - h);
    }

    /** Runs {@code action} with System.err captured, and returns what it printed. */
    static String captureStdErr(Runnable action) {
        PrintStream old = System.err;
        ByteArrayOutputStream buf = new ByteArrayOutputStream();
        PrintStream tmp = new PrintStream(buf, true, StandardCharsets.UTF_8);
        System.setErr(tmp);
        try {
            action.run();
        } finally {
            System.setErr(old);
            tmp.flush();
        }
        return buf.toString(StandardCharsets.UTF_8);
    }

    /** @return the largest |coordinate| of any mass (NaN if a coordinate is NaN). */
    static double maxAbsCoordinate(PhysicalModel pm) {
        double m = 0;
        Vect3D p = new Vect3D();
        for (int i = 0, n = pm.getNumberOfMats(); i < n; i++) {
            p = pm.getMatPosAt(i);
            double a = Math.max(Math.abs(p.x), Math.max(Math.abs(p.y), Math.abs(p.z)));
            if (Double.isNaN(a)) {
                return Double.NaN;
            }
            m = Math.max(m, a);
        }
        return m;
    }

    /** Fails unless every position, velocity and force of every mass is finite. */
    static void assertFiniteState(PhysicalModel pm, String scene) {
        for (int i = 0, n = pm.getNumberOfMats(); i < n; i++) {
            Vect3D p = pm.getMatPosAt(i);
            Vect3D v = pm.getMatVelAt(i);
            Vect3D f = pm.getMatFrcAt(i);
            if (!p.isFinite() || !v.isFinite() || !f.isFinite()) {
                fail(scene + ": mass " + pm.getMatNameAt(i) + " is not finite at step " + pm.getStepCount()
                        + ": pos " + p + " vel " + v + " force " + f);
            }
        }
        assertTrue(Double.isFinite(pm.getTotalEnergy()), scene + ": total energy " + pm.getTotalEnergy());
    }

    /**
     * The function G of the class comment for a 1D network in ALGO_UNITS built from Mass1D, Osc1D, Ground1D
     * and SpringDamper1D (air friction included). Oscillators' rest positions are their initial z, given in
     * {@code oscRest} by name. Velocities are read as per-second values and divided by the rate.
     */
    static double lyapunov1D(PhysicalModel pm, Map<String, Double> oscRest) {
        double fs = pm.getSimRate();
        double friction = pm.getFriction();
        int nm = pm.getNumberOfMats();
        Map<String, double[]> state = new HashMap<>();
        double g = 0;
        for (int i = 0; i < nm; i++) {
            String name = pm.getMatNameAt(i);
            String type = pm.getMatTypeAt(i).name();
            double z = pm.getMatPosAt(i).z;
            double v = pm.getMatVelAt(i).z / fs;
            state.put(name, new double[] {z, v});
            if (type.startsWith("Ground")) {
                continue;
            }
            if (!type.equals("Mass1D") && !type.equals("Osc1D")) {
                throw new IllegalArgumentException("lyapunov1D: unsupported module " + type);
            }
            double m = pm.getMatMass(name);
            double zeta = friction;
            if (type.equals("Osc1D")) {
                double r = oscRest.get(name);
                double k = pm.getMatStiffness(name);
                zeta += pm.getMatDamping(name);
                g += 0.5 * k * (z - r) * (z - v - r);
            }
            g += 0.5 * (m - zeta / 2) * v * v;
        }
        for (int j = 0, nl = pm.getNumberOfLinks(); j < nl; j++) {
            String name = pm.getLinkNameAt(j);
            if (!pm.getLinkTypeAt(j).name().equals("SpringDamper1D")) {
                throw new IllegalArgumentException("lyapunov1D: unsupported link " + pm.getLinkTypeAt(j).name());
            }
            String[] ends = pm.getLinkMatNames(name);
            double[] a = state.get(ends[0]);
            double[] b = state.get(ends[1]);
            double l0 = pm.getLinkDRest(name);
            double e = a[0] - b[0] - l0;
            double ePrev = (a[0] - a[1]) - (b[0] - b[1]) - l0;
            double dv = a[1] - b[1];
            g += 0.5 * pm.getLinkStiffness(name) * e * ePrev - 0.25 * pm.getLinkDamping(name) * dv * dv;
        }
        return g;
    }

    /** A small deterministic generator (SplittableRandom is used where streams are needed). */
    static java.util.SplittableRandom rng(long seed) {
        return new java.util.SplittableRandom(seed);
    }

    /**
     * A damped 12-mass 1D chain between two Ground1D ends (SpringDamper1D K 0.7, Z 0.001, masses 1 to 3) whose
     * coordinates are {@code scale} times a fixed random shape: a linear scene, so any power-of-two scale is exact.
     */
    static PhysicalModel dampedChain1D(double scale) {
        PhysicalModel pm = new PhysicalModel(1000);
        java.util.SplittableRandom rnd = new java.util.SplittableRandom(99);
        pm.addGround1D("g", new Vect3D());
        for (int i = 0; i < 12; i++) {
            pm.addMass1D("m" + i, 1.0 + i % 3, new Vect3D(0, 0, scale * (2 * rnd.nextDouble() - 1)), new Vect3D());
        }
        for (int i = 0; i <= 12; i++) {
            pm.addSpringDamper1D("k" + i, 0, 0.7, 0.001, i == 0 ? "g" : "m" + (i - 1), i == 12 ? "g" : "m" + i);
        }
        pm.init();
        return pm;
    }
}
