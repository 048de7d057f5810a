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
}
