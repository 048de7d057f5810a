package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.function.Supplier;

/**
 * Test helper (not a test class): a complete textual snapshot of a {@link PhysicalModel}, read through
 * its public API only, so two models can be compared exactly ("the model is unchanged").
 * Doubles are printed with {@link Double#toString(double)}, so equal text means bit-equal values.
 */
final class ModelState {
    private ModelState() {
    }

    /** @return every observable piece of state of the model, one item per line. */
    static String of(PhysicalModel m, String... subsets) {
        StringBuilder sb = new StringBuilder();
        sb.append("rates ").append(m.getSimRate()).append(' ').append(m.getDisplayRate())
                .append(" system ").append(m.getParamSystem())
                .append(" steps ").append(m.getStepCount()).append('\n');
        sb.append("gravity ").append(m.getGravity()).append(' ').append(m.getGravityDirection())
                .append(" friction ").append(m.getFriction()).append('\n');
        int nm = m.getNumberOfMats();
        sb.append("mats ").append(nm).append('\n');
        for (int i = 0; i < nm; i++) {
            String name = m.getMatNameAt(i);
            String type = m.getMatTypeAt(i).name();
            sb.append("  [").append(i).append("] ").append(name).append(' ').append(type)
                    .append(" idx=").append(m.getMatIndex(name))
                    .append(" pos=").append(m.getMatPosAt(i))
                    .append(" vel=").append(m.getMatVelAt(i))
                    .append(" frc=").append(m.getMatFrcAt(i));
            if (isInertial(type)) {
                sb.append(" M=").append(m.getMatMass(name));
            }
            if (type.startsWith("Osc")) {
                sb.append(" K=").append(m.getMatStiffness(name)).append(" Z=").append(m.getMatDamping(name));
            }
            sb.append('\n');
        }
        int nl = m.getNumberOfLinks();
        sb.append("links ").append(nl).append('\n');
        for (int i = 0; i < nl; i++) {
            String name = m.getLinkNameAt(i);
            String[] ends = m.getLinkMatNames(name);
            sb.append("  [").append(i).append("] ").append(name).append(' ').append(m.getLinkTypeAt(i).name())
                    .append(" idx=").append(m.getLinkIndex(name))
                    .append(" ends=").append(ends[0]).append(',').append(ends[1])
                    .append(" K=").append(m.getLinkStiffness(name))
                    .append(" Z=").append(m.getLinkDamping(name))
                    .append(" L=").append(m.getLinkDRest(name))
                    .append(" d=").append(m.getLinkDistanceAt(i))
                    .append(" e=").append(m.getLinkElongationAt(i));
            Interaction h = m.getInteraction(name);
            if (h instanceof Attractor3D) {
                sb.append(" A=").append(((Attractor3D) h).getAttraction());
            }
            if (h instanceof PlaneContact3D) {
                sb.append(" plane=").append(((PlaneContact3D) h).getOrientation()).append('@')
                        .append(((PlaneContact3D) h).getPlanePosition());
            }
            sb.append('\n');
        }
        for (String s : subsets) {
            sb.append("subset ").append(s).append(' ').append(String.join(",", m.getSubsetMembers(s))).append('\n');
        }
        return sb.toString();
    }

    static boolean isInertial(String type) {
        return type.equals("Mass3D") || type.equals("Mass2DPlane") || type.equals("Mass1D")
                || type.equals("Osc3D") || type.equals("Osc1D");
    }

    /**
     * Asserts that two models built by the same recipe are in the same state now, and still after
     * running the same number of steps on both.
     */
    static void assertSameEvolution(PhysicalModel expected, PhysicalModel actual, int steps, String... subsets) {
        assertEquals(of(expected, subsets), of(actual, subsets), "state right after the operation");
        expected.computeNSteps(steps);
        actual.computeNSteps(steps);
        assertEquals(of(expected, subsets), of(actual, subsets), "state after " + steps + " more steps");
    }

    /** Convenience for twin models: builds two models with the same recipe. */
    static PhysicalModel[] twins(Supplier<PhysicalModel> recipe) {
        return new PhysicalModel[] {recipe.get(), recipe.get()};
    }
}
