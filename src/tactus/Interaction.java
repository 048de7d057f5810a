package tactus;

import tactus.internal.calls.ModuleCalls.LinkParam;

/**
 * A handle on one interaction module of a {@link PhysicalModel}: a thin view onto its slot in the
 * engine's arrays. Handles stay valid until the interaction or one of its masses is removed, or the
 * model is cleared; after that every method throws {@link IllegalStateException}.
 */
public abstract class Interaction extends Module {
    Interaction(ModuleHandles handles, int id) {
        super(handles, id);
    }

    @Override
    public String getName() {
        checkValid();
        return calls.linkName(id);
    }

    @Override
    public String getType() {
        checkValid();
        return getClass().getSimpleName();
    }

    /** {@return the handle of the first mass} */
    public Mass getMass1() {
        checkValid();
        return calls.read(() -> handles.mass(calls.linkEnd(id, false)));
    }

    /** {@return the handle of the second mass (the same as the first for a plane contact)} */
    public Mass getMass2() {
        checkValid();
        return calls.read(() -> handles.mass(calls.linkEnd(id, true)));
    }

    /** {@return the current distance between the two masses (for a plane contact, the gap to the plane)} */
    public double getDistance() {
        return param(LinkParam.DISTANCE);
    }

    /** {@return the distance minus the length parameter (rest length, threshold, radius, offset or limit)} */
    public double getElongation() {
        return param(LinkParam.ELONGATION);
    }

    /** Reads a number of this interaction (its handle's check first, for a message that names it). */
    double param(LinkParam p) {
        checkValid();
        return calls.linkParam(id, p);
    }

    /** Sets a parameter of this interaction after checking the value is a number (the room checks the rest). */
    void set(String op, String param, LinkParam p, double v) {
        checkFinite(op, param, v);
        calls.setLinkParam(id, op, p, v);
    }

    double stiffness() {
        return param(LinkParam.STIFFNESS);
    }

    void stiffness(double K) {
        set("setStiffness", "K", LinkParam.STIFFNESS, K);
    }

    double damping() {
        return param(LinkParam.DAMPING);
    }

    void damping(double Z) {
        set("setDamping", "Z", LinkParam.DAMPING, Z);
    }

    double length() {
        return param(LinkParam.LENGTH);
    }

    void length(String op, double d) {
        set(op, "d", LinkParam.LENGTH, d);
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
        checkValid();
        return calls.linkAux(id, op, index);
    }

    /** Sets parameter {@code index} beyond K, Z and the length, in the model's units. */
    void aux(String op, int index, double value) {
        checkFinite(op, "value", value);
        calls.setLinkAux(id, op, index, value);
    }
}
