package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/**
 * A handle on one interaction module of a {@link PhysicalModel}: a thin view onto its slot in the
 * engine's arrays. Handles stay valid until the interaction or one of its masses is removed, or the
 * model is cleared; after that every method throws {@link IllegalStateException}.
 */
public abstract class Interaction extends Module {
    Interaction(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }


    @Override
    public String getName() {
        enter();
        try {
            return core.dir.linkName(id);
        } finally {
            exit();
        }
    }

    @Override
    public String getType() {
        checkValid();
        return getClass().getSimpleName();
    }

    /** @return the handle of the first mass. */
    public Mass getMass1() {
        enter();
        try {
            return (Mass) core.dir.massHandle(core.engine.linkMassA(id));
        } finally {
            exit();
        }
    }

    /** @return the handle of the second mass (the same as the first for a plane contact). */
    public Mass getMass2() {
        enter();
        try {
            return (Mass) core.dir.massHandle(core.engine.linkMassB(id));
        } finally {
            exit();
        }
    }

    /** @return the current distance between the two masses (for a plane contact, the gap to the plane). */
    public double getDistance() {
        enter();
        try {
            return core.params.linkDistance(id);
        } finally {
            exit();
        }
    }

    /** @return the distance minus the length parameter (rest length, threshold, radius, offset or limit). */
    public double getElongation() {
        enter();
        try {
            return core.params.linkElongation(id);
        } finally {
            exit();
        }
    }

    double stiffness() {
        enter();
        try {
            return core.params.linkStiffness(id);
        } finally {
            exit();
        }
    }

    void stiffness(double K) {
        checkFinite("setStiffness", "K", K);
        enter();
        try {
            core.params.setLink("setStiffness", id, K, Double.NaN, Double.NaN);
        } finally {
            exit();
        }
    }

    double damping() {
        enter();
        try {
            return core.params.linkDamping(id);
        } finally {
            exit();
        }
    }

    void damping(double Z) {
        checkFinite("setDamping", "Z", Z);
        enter();
        try {
            core.params.setLink("setDamping", id, Double.NaN, Z, Double.NaN);
        } finally {
            exit();
        }
    }

    double length() {
        enter();
        try {
            return core.params.linkLength(id);
        } finally {
            exit();
        }
    }

    void length(String op, double d) {
        checkFinite(op, "d", d);
        enter();
        try {
            core.params.setLink(op, id, Double.NaN, Double.NaN, d);
        } finally {
            exit();
        }
    }

    // ---- the parameters beyond K, Z and the length (mi.lib's nonlinear interactions)

    /**
     * Reads a parameter beyond stiffness, damping and length by its name, one of
     * {@link linkModuleType#extraParameterNames()} of this interaction's type (for example {@code "Kmax"}).
     *
     * @throws IllegalArgumentException when the type has no parameter of that name
     */
    public double getExtraParameter(String name) {
        return aux("getExtraParameter", extraIndex("getExtraParameter", name));
    }

    /**
     * Sets a parameter beyond stiffness, damping and length by its name, one of
     * {@link linkModuleType#extraParameterNames()} of this interaction's type, in the model's units.
     *
     * @throws IllegalArgumentException when the type has no parameter of that name, or the value is out of range
     */
    public void setExtraParameter(String name, double value) {
        aux("setExtraParameter", extraIndex("setExtraParameter", name), value);
    }

    private int extraIndex(String op, String name) {
        String[] names = linkModuleType.valueOf(getType()).extraParameterNames();
        for (int i = 0; i < names.length; i++) {
            if (names[i].equals(name)) {
                return i;
            }
        }
        throw new IllegalArgumentException(op + "(\"" + name + "\"): a " + getType() + " has no such parameter; its"
                + " extra parameters are " + java.util.Arrays.toString(names));
    }

    /** @return parameter {@code index} beyond K, Z and the length, in the model's units. */
    double aux(String op, int index) {
        enter();
        try {
            return core.params.aux(op, id, index);
        } finally {
            exit();
        }
    }

    /** Sets parameter {@code index} beyond K, Z and the length, in the model's units. */
    void aux(String op, int index, double value) {
        enter();
        try {
            core.params.setAux(op, id, index, value);
        } finally {
            exit();
        }
    }
}
