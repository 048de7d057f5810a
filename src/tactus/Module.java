package tactus;

import tactus.internal.calls.ModuleCalls;
import tactus.internal.model.Check;

/**
 * A handle on one module (a mass or an interaction) of a {@link PhysicalModel}: a thin view onto its slot
 * in the engine's arrays. A handle stays valid until its module leaves the model (removed, cleared, or a
 * mass turned into a fixed point); after that every method throws {@link IllegalStateException}.
 */
public abstract class Module {
    /** The handles of this module's model (the one place that makes them). */
    final ModuleHandles handles;
    /** The calls this handle makes, by its module id: the same door the model's own calls go through. */
    final ModuleCalls calls;
    final int id;
    private volatile boolean valid = true;

    Module(ModuleHandles handles, int id) {
        this.handles = handles;
        this.calls = handles.calls;
        this.id = id;
    }

    void invalidate() {
        valid = false;
    }

    void checkValid() {
        if (!valid) {
            throw new IllegalStateException("this " + getClass().getSimpleName()
                    + " handle is no longer part of its model (removed, cleared or made fixed)");
        }
    }

    /** Validates a vector argument of a handle that is still part of its model, building the error message (which names this module) only on failure. */
    void checkVector(String op, String param, Vect3D v) {
        checkValid();
        if (v == null || !v.isFinite()) {
            Check.vector(op, toString(), param, v);
        }
    }

    /** Validates a number argument, building the error message only on failure. */
    void checkFinite(String op, String param, double v) {
        checkValid();
        if (!Double.isFinite(v)) {
            Check.finite(op, toString(), param, v);
        }
    }

    /** {@return true while the module is part of its model} */
    public boolean isValid() {
        return valid;
    }

    /** {@return the unique name of this module} */
    public abstract String getName();

    /** {@return the module type, for example "Mass3D" or "SpringDamper3D"} */
    public abstract String getType();

    @Override
    public String toString() {
        return valid ? getType() + "(\"" + getName() + "\")" : getClass().getSimpleName() + "(removed)";
    }
}
