package tactus.export;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;

/**
 * What an exported Faust program listens to, where it takes forces in and which parameters it turns into
 * sliders. Each call returns this object, so options chain:
 * <pre>
 * FaustExportOptions o = new FaustExportOptions()
 *     .name("string")
 *     .listen("m12", 2)            // output 1: z of m12 minus its position now
 *     .forceInput("m3", 2)         // input 1: a force along z on m3, in the model's force units
 *     .slider("stiffness", FaustExportOptions.STIFFNESS, "string");   // a link subset, or module names
 * </pre>
 * Validation against the model happens at export ({@link FaustExporter}), with an exception naming the option.
 */
public final class FaustExportOptions {
    /** Slider parameter: the mass M of masses and oscillators (ALGO_UNITS: a number; REAL_UNITS: kg). */
    public static final String MASS = "mass";
    /** Slider parameter: the stiffness K of interactions or oscillators (ALGO: per step²; REAL: N/m). */
    public static final String STIFFNESS = "stiffness";
    /** Slider parameter: the damping Z of interactions or oscillators (ALGO: per step; REAL: N·s/m). */
    public static final String DAMPING = "damping";
    /** Slider parameter: the rest length (or threshold, radius) of interactions, in length units. */
    public static final String DIST = "dist";

    /** One listening point: a Faust output. */
    static final class Listen {
        final String mass;
        final int axis;
        final double gain;

        Listen(String mass, int axis, double gain) {
            this.mass = mass;
            this.axis = axis;
            this.gain = gain;
        }
    }

    /** One force input: a Faust input. */
    static final class Input {
        final String mass;
        final int axis;

        Input(String mass, int axis) {
            this.mass = mass;
            this.axis = axis;
        }
    }

    /** One slider. */
    static final class Slider {
        final String label;
        final String param;
        final List<String> elements;
        final double min;
        final double max;

        Slider(String label, String param, List<String> elements, double min, double max) {
            this.label = label;
            this.param = param;
            this.elements = elements;
            this.min = min;
            this.max = max;
        }
    }

    private String name = "tactus";
    private final List<Listen> listens = new ArrayList<>();
    private final List<Input> inputs = new ArrayList<>();
    private final List<Slider> sliders = new ArrayList<>();

    /** Sets the program's name (Faust metadata {@code name}); default "tactus". */
    public FaustExportOptions name(String name) {
        if (name == null || name.isEmpty() || name.indexOf('"') >= 0 || name.indexOf('\n') >= 0) {
            throw new IllegalArgumentException("FaustExportOptions.name: a non-empty name without quotes, got "
                    + name);
        }
        this.name = name;
        return this;
    }

    /** Adds an output: the coordinate of a mass along an axis (0 = x, 1 = y, 2 = z) minus its value now. */
    public FaustExportOptions listen(String mass, int axis) {
        return listen(mass, axis, 1);
    }

    /**
     * Adds an output: gain times (the coordinate of a mass along an axis minus its value at export), which is
     * what a {@code PhyUGen} listening point reads ({@code listenToMass(mass, axis, gain, pan)}, before its DC
     * blocker and pan).
     *
     * @param axis 0 = x, 1 = y, 2 = z
     * @param gain output units per length unit, finite
     */
    public FaustExportOptions listen(String mass, int axis, double gain) {
        checkName("listen", mass);
        checkAxis("listen", mass, axis);
        if (!Double.isFinite(gain)) {
            throw new IllegalArgumentException("FaustExportOptions.listen(\"" + mass + "\"): gain must be finite, got "
                    + gain);
        }
        listens.add(new Listen(mass, axis, gain));
        return this;
    }

    /**
     * Adds an input: a force on a mass along an axis, in the model's force units (ALGO_UNITS: mass × units /
     * step²; REAL_UNITS: N), added for one step per sample, as {@code triggerForceImpulse} does.
     */
    public FaustExportOptions forceInput(String mass, int axis) {
        checkName("forceInput", mass);
        checkAxis("forceInput", mass, axis);
        inputs.add(new Input(mass, axis));
        return this;
    }

    /**
     * Adds a slider ({@code hslider}) for one parameter shared by some modules, set to their current value, from
     * 0 (a tenth of it for a mass) to twice it.
     *
     * @param label the slider's label in the Faust interface
     * @param param {@link #MASS}, {@link #STIFFNESS}, {@link #DAMPING} or {@link #DIST}
     * @param elements names of masses or interactions, or of mass or link subsets; all must have the same value
     */
    public FaustExportOptions slider(String label, String param, String... elements) {
        return slider(label, param, Double.NaN, Double.NaN, elements);
    }

    /** Adds a slider as {@link #slider(String, String, String...)} with its range given (model units). */
    public FaustExportOptions slider(String label, String param, double min, double max, String... elements) {
        checkName("slider", label);
        if (label.indexOf('"') >= 0) {
            throw new IllegalArgumentException("FaustExportOptions.slider: a label without quotes, got " + label);
        }
        if (!Arrays.asList(MASS, STIFFNESS, DAMPING, DIST).contains(param)) {
            throw new IllegalArgumentException("FaustExportOptions.slider(\"" + label + "\"): param must be mass, "
                    + "stiffness, damping or dist, got " + param);
        }
        if (elements == null || elements.length == 0) {
            throw new IllegalArgumentException("FaustExportOptions.slider(\"" + label + "\"): name at least one "
                    + "module or subset");
        }
        if (!Double.isNaN(min) || !Double.isNaN(max)) {
            if (!(Double.isFinite(min) && Double.isFinite(max) && min < max)) {
                throw new IllegalArgumentException("FaustExportOptions.slider(\"" + label + "\"): need finite min < max,"
                        + " got " + min + ", " + max);
            }
        }
        for (Slider s : sliders) {
            if (s.label.equals(label)) {
                throw new IllegalArgumentException("FaustExportOptions.slider: label \"" + label + "\" used twice");
            }
        }
        sliders.add(new Slider(label, param, Collections.unmodifiableList(Arrays.asList(elements.clone())), min, max));
        return this;
    }

    String name() {
        return name;
    }

    List<Listen> listens() {
        return listens;
    }

    List<Input> inputs() {
        return inputs;
    }

    List<Slider> sliders() {
        return sliders;
    }

    private static void checkName(String op, String name) {
        if (name == null || name.isEmpty()) {
            throw new IllegalArgumentException("FaustExportOptions." + op + ": a name is needed, got " + name);
        }
    }

    private static void checkAxis(String op, String mass, int axis) {
        if (axis < 0 || axis > 2) {
            throw new IllegalArgumentException("FaustExportOptions." + op + "(\"" + mass + "\"): axis must be 0, 1 or 2,"
                    + " got " + axis);
        }
    }
}
