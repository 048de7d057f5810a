package tactus.bench;

import java.util.Locale;
import java.util.Random;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * Scenes whose step is dominated by a moving contact group, for {@link BeforeAfter} ({@code --scene=line-N} and
 * {@code --scene=lattice-N}): N {@code Mass3D} members, each tethered to a ground of its own by a SpringDamper3D
 * (K 0.02, no damping: about 44 steps per swing) and started 2 thresholds away from it in a random direction, so
 * that the fastest member moves about 0.28 threshold per step, more than half the group's skin (0.15 threshold): the
 * neighbour list is rebuilt at nearly every step, as the soak's beads are once its chaos sets them moving. One
 * contact group over all members (threshold 0.25, K 0.05, Z 0), per-step units ({@code ALGO_UNITS}) at 44.1 kHz.
 *
 * <ul>
 *   <li>{@code line-N}: the grounds along x, 4 thresholds apart, as the soak's beads on their string: the members'
 *       bounding box spans some 50 x 5 x 5 grid cells for 16 members;
 *   <li>{@code lattice-N}: the grounds on a cubic lattice 2 thresholds apart: a compact group, each member within
 *       reach of its lattice neighbours at times.
 * </ul>
 *
 * <p>{@code main} prints a checksum of every member's position after a number of steps, built only through the
 * public API, so that two builds (this tree and {@code build/beforeafter/<rev>/classes}) can be compared for
 * bit-identical trajectories: {@code java -cp <library classes>:<tools classes>:<jars> tactus.bench.GroupScenes}.
 */
public final class GroupScenes {
    /** The contact group's threshold (model units). */
    static final double THRESHOLD = 0.25;

    private GroupScenes() {
    }

    /**
     * @param scene {@code line-N} or {@code lattice-N}
     * @return the scene's model, initialised
     */
    public static PhysicalModel create(String scene) {
        int dash = scene.lastIndexOf('-');
        int n = Integer.parseInt(scene.substring(dash + 1));
        switch (scene.substring(0, dash)) {
            case "line":
                return build(n, false);
            case "lattice":
                return build(n, true);
            default:
                throw new IllegalArgumentException("unknown group scene " + scene + " (line-N, lattice-N)");
        }
    }

    /** @return whether a scene name is one of these scenes */
    public static boolean isGroupScene(String scene) {
        return scene.matches("(line|lattice)-[0-9]+");
    }

    private static PhysicalModel build(int n, boolean lattice) {
        PhysicalModel mdl = new PhysicalModel(44100, 60, paramSystem.ALGO_UNITS);
        mdl.setGravity(0);
        mdl.setFriction(0);
        Random random = new Random(27);
        int side = (int) Math.ceil(Math.cbrt(n));
        mdl.createMatSubset("members");
        for (int i = 0; i < n; i++) {
            double gx, gy, gz;
            if (lattice) {
                gx = 2 * THRESHOLD * (i % side);
                gy = 2 * THRESHOLD * ((i / side) % side);
                gz = 2 * THRESHOLD * (i / (side * side));
            } else {
                gx = 4 * THRESHOLD * i;
                gy = 0;
                gz = 0;
            }
            double ux = random.nextGaussian(), uy = random.nextGaussian(), uz = random.nextGaussian();
            double a = 2 * THRESHOLD / Math.sqrt(ux * ux + uy * uy + uz * uz);
            mdl.addGround3D("g" + i, new Vect3D(gx, gy, gz));
            mdl.addMass3D("m" + i, 1.0, new Vect3D(gx + a * ux, gy + a * uy, gz + a * uz), new Vect3D(0, 0, 0));
            mdl.addSpringDamper3D("t" + i, 0, 0.02, 0, "g" + i, "m" + i);
            mdl.addMatToSubset("m" + i, "members");
        }
        mdl.addContactGroup("members", THRESHOLD, 0.05, 0);
        mdl.init();
        return mdl;
    }

    /**
     * Prints, for each scene, a checksum of the members' positions (their bits) after a number of steps.
     *
     * @param args scene names (default: line and lattice with 16, 200 and 2,000 members) and {@code --steps=N}
     *     (default 20,000)
     */
    public static void main(String[] args) {
        int steps = 20_000;
        java.util.List<String> scenes = new java.util.ArrayList<>();
        for (String a : args) {
            if (a.startsWith("--steps=")) {
                steps = Integer.parseInt(a.substring(8));
            } else {
                scenes.add(a);
            }
        }
        if (scenes.isEmpty()) {
            for (String kind : new String[] {"line", "lattice"}) {
                for (int n : new int[] {16, 200, 2000}) {
                    scenes.add(kind + "-" + n);
                }
            }
        }
        for (String scene : scenes) {
            PhysicalModel mdl = create(scene);
            int n = Integer.parseInt(scene.substring(scene.lastIndexOf('-') + 1));
            long sum = 0;
            Vect3D p = new Vect3D();
            for (int s = 0; s < steps; s++) {
                mdl.computeStep();
                if (s % 1000 == 999) {
                    for (int i = 0; i < n; i++) {
                        mdl.getMatPosition("m" + i, p);
                        sum = 31 * sum + Double.doubleToLongBits(p.x);
                        sum = 31 * sum + Double.doubleToLongBits(p.y);
                        sum = 31 * sum + Double.doubleToLongBits(p.z);
                    }
                }
            }
            System.out.printf(Locale.ROOT, "%s: %d steps, checksum %016x, diverged %b%n", scene, steps, sum,
                    mdl.isDiverged());
        }
    }
}
