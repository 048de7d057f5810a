package tactus.io;

import java.util.Arrays;
import java.util.List;
import tactus.PhysicalModel;
import tactus.linkModuleType;

/**
 * The module type names of the file format, in the order the paper's engine writes its groups, and
 * the one place that turns a model's type (a String label today, a module-type enum later) into them.
 */
final class FileTypes {
    /** Mass groups of the {@code MAT} section; PosInput3D is a Tactus addition at the end. */
    static final List<String> MASS_GROUPS = Arrays.asList("Ground1D", "Ground3D", "HapticInput3D", "Mass1D",
            "Mass2DPlane", "Mass3D", "Mass3DSimple", "Osc1D", "Osc3D", "PosInput3D");
    /** Interaction groups of the {@code Link} section; Attractor3D is a Tactus addition at the end. */
    static final List<String> LINK_GROUPS = linkGroups();

    private FileTypes() {
    }

    /** The paper's groups, then the Tactus additions: Attractor3D and every kind with extra parameters, by type. */
    private static List<String> linkGroups() {
        List<String> g = new java.util.ArrayList<>(Arrays.asList("Damper3D", "Bubble3D", "Contact3D",
                "PlaneContact3D", "Rope3D", "Spring3D", "SpringDamper1D", "SpringDamper3D", "Attractor3D"));
        for (linkModuleType t : linkModuleType.values()) {
            if (t.isNonlinear()) {
                g.add(t.name());
            }
        }
        return java.util.Collections.unmodifiableList(g);
    }

    /** @return true for a type whose parameters beyond K, Z and the length are named by its descriptor. */
    static boolean hasExtraParameters(String type) {
        return LINK_GROUPS.contains(type) && linkModuleType.valueOf(type).isNonlinear();
    }

    /** @return the names of the parameters of a type beyond K, Z and the length, as attributes of the file. */
    static String[] extraParameters(String type) {
        return linkModuleType.valueOf(type).extraParameterNames();
    }

    /** @return the file type name of mass {@code i} (works whether the model returns a String or an enum). */
    static String massType(PhysicalModel model, int i) {
        return String.valueOf(model.getMatTypeAt(i));
    }

    /** @return the file type name of interaction {@code i}. */
    static String linkType(PhysicalModel model, int i) {
        return String.valueOf(model.getLinkTypeAt(i));
    }

    /** @return true for the masses that carry an inertia and a velocity. */
    static boolean isInertial(String type) {
        switch (type) {
            case "Mass1D":
            case "Mass2DPlane":
            case "Mass3D":
            case "Mass3DSimple":
            case "Osc1D":
            case "Osc3D":
                return true;
            default:
                return false;
        }
    }

    /** @return true for the oscillators, which carry a stiffness and a damping. */
    static boolean isOscillator(String type) {
        return type.equals("Osc1D") || type.equals("Osc3D");
    }

    /** @return true for the kinematic inputs, which carry an EWMA smoothing length. */
    static boolean isInput(String type) {
        return type.equals("HapticInput3D") || type.equals("PosInput3D");
    }

    /** @return true for the interactions that act on a single mass. */
    static boolean isSingleMass(String type) {
        return type.equals("PlaneContact3D");
    }
}
