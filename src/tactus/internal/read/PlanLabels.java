package tactus.internal.read;

import java.util.HashMap;
import java.util.Map;

/**
 * Describes the computations of a compiled step plan in the user's words, one label per computation: what a
 * scene simulates, and therefore pays for.
 */
public final class PlanLabels {
    private static final Map<String, String> LABELS = new HashMap<>();

    static {
        LABELS.put("Free3D", "free 3D masses");
        LABELS.put("Medium3D", "3D masses with gravity or friction");
        LABELS.put("Plane2D", "masses in a plane");
        LABELS.put("Line1D", "1D masses");
        LABELS.put("Osc3D", "3D oscillators");
        LABELS.put("Osc1D", "1D oscillators");
        LABELS.put("Input3D", "input modules");
        LABELS.put("Fixed", "fixed points");
        LABELS.put("Driven3D", "velocity-driven masses");
        LABELS.put("Spring", "springs");
        LABELS.put("Damper", "dampers");
        LABELS.put("SpringDamper", "spring-dampers");
        LABELS.put("SpringDamper1D", "1D spring-dampers");
        LABELS.put("StencilKernel", "spring-dampers in dense runs");
        LABELS.put("Stretched", "ropes and bubbles");
        LABELS.put("Proximity", "contacts");
        LABELS.put("Plane", "plane contacts");
        LABELS.put("Attractor", "attractors");
        LABELS.put("ContactGroupKernel", "contact groups");
        LABELS.put("Elastic3D", "nonlinear spring-dampers and plucks");
        LABELS.put("Elastic1D", "1D nonlinear spring-dampers and plucks");
        LABELS.put("Bow3D", "bows");
        LABELS.put("Bow1D", "1D bows");
        LABELS.put("Contact3D", "clipped contacts");
        LABELS.put("Contact1D", "1D clipped contacts");
    }

    private PlanLabels() {
    }

    /** @return the user-facing label of each engine computation, in order. */
    public static String[] of(String[] kernelNames) {
        String[] out = new String[kernelNames.length];
        for (int i = 0; i < out.length; i++) {
            String label = LABELS.get(kernelNames[i]);
            if (label == null) {
                throw new IllegalStateException("Tactus internal error: no label for step computation "
                        + kernelNames[i]);
            }
            out[i] = label;
        }
        return out;
    }
}
