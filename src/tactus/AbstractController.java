package tactus;

import java.util.HashMap;
import java.util.Map;
import tactus.internal.model.PaperLeniency;

/**
 * The base of the paper engine's parameter controllers: it names a subset and one of its parameters ("mass",
 * "stiffness", "damping", "dist", or "distX" for the spacing of a mass subset along x), and maps an input range
 * {@code [vmin, vmax]} linearly onto a value range {@code [min, max]}, set with {@link #setParam(String, float)}.
 */
public class AbstractController {
    /** The model the controller acts on. */
    protected final PhysicalModel pm;
    /** The parameter it controls. */
    protected final String param;
    /** The subset it controls. */
    protected final String subsetName;
    /** Slope of the linear map. */
    protected float a;
    /** Offset of the linear map. */
    protected float b;
    private final Map<String, Float> params = new HashMap<>();

    /**
     * Creates a controller of one parameter of a subset.
     *
     * @param pm the model
     * @param subsetName a mass or link subset (one that does not exist is forgiven as in the paper's engine, with
     *     one warning, unless the model is strict: {@link PhysicalModel#setStrict(boolean)})
     * @param param "mass", "stiffness", "damping", "dist" or "distX"
     */
    public AbstractController(PhysicalModel pm, String subsetName, String param) {
        if (pm == null) {
            throw new IllegalArgumentException("controller of \"" + subsetName + "\": the model must not be null");
        }
        if (!("mass".equals(param) || "stiffness".equals(param) || "damping".equals(param) || "dist".equals(param)
                || "distX".equals(param))) {
            throw new IllegalArgumentException("controller of \"" + subsetName + "\": param must be \"mass\", "
                    + "\"stiffness\", \"damping\", \"dist\" or \"distX\", got \"" + param + "\"");
        }
        if (!pm.subsetExists(subsetName)) {
            if (pm.isStrict() || subsetName == null) {
                throw new IllegalArgumentException("controller of \"" + subsetName + "\": no such subset");
            }
            // the paper's engine made the controller anyway; its changes go through the same forgiving calls
            pm.core.lenient.forgive(PaperLeniency.Kind.NO_SUCH_SUBSET, "controller", subsetName, "no such subset",
                    "the controller was made, and changes nothing");
        }
        this.pm = pm;
        this.subsetName = subsetName;
        this.param = param;
        setParam("vmin", 0);
        setParam("vmax", 1);
        setParam("min", 0);
        setParam("max", 1);
    }

    /** Sets one of "min", "max" (value range) or "vmin", "vmax" (input range) and updates the linear map. */
    public void setParam(String key, float value) {
        if (!Float.isFinite(value)) {
            throw new IllegalArgumentException("setParam(\"" + key + "\"): the value must be finite, got " + value);
        }
        params.put(key, value);
        float vmin = get("vmin");
        float vmax = get("vmax");
        a = vmax == vmin ? 0 : (get("max") - get("min")) / (vmax - vmin);
        b = get("max") - a * vmax;
    }

    private float get(String key) {
        Float v = params.get(key);
        return v == null ? 0 : v;
    }

    /** {@return the name of the controlled subset} */
    public String getSubsetName() {
        return subsetName;
    }

    /** {@return the controlled parameter} */
    public String getParamName() {
        return param;
    }

    /** @return the value the linear map gives for an input {@code v}: {@code a v + b}. */
    float linearScale(float v) {
        return a * v + b;
    }
}
