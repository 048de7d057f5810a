package tactus;

import tactus.engine.LinkKind;

/**
 * A handle on one interaction module of a {@link PhysicalModel}: a thin view onto its slot in the
 * engine's arrays. Handles stay valid until the interaction or one of its masses is removed, or the
 * model is cleared; after that every method throws {@link IllegalStateException}.
 */
public abstract class Interaction extends Module {
    Interaction(PhysicalModel model, int id) {
        super(model, id);
    }

    static Interaction create(PhysicalModel model, int id, LinkKind kind) {
        switch (kind) {
            case SPRING3D:
                return new Spring3D(model, id);
            case DAMPER3D:
                return new Damper3D(model, id);
            case SPRING_DAMPER3D:
                return new SpringDamper3D(model, id);
            case SPRING_DAMPER1D:
                return new SpringDamper1D(model, id);
            case ROPE3D:
                return new Rope3D(model, id);
            case CONTACT3D:
                return new Contact3D(model, id);
            case BUBBLE3D:
                return new Bubble3D(model, id);
            case PLANE_CONTACT3D:
                return new PlaneContact3D(model, id);
            case ATTRACTOR3D:
                return new Attractor3D(model, id);
            default:
                throw new IllegalStateException("no handle for " + kind);
        }
    }

    @Override
    public String getName() {
        checkValid();
        return model.linkName(id);
    }

    @Override
    public String getType() {
        checkValid();
        return getClass().getSimpleName();
    }

    /** @return the handle of the first mass. */
    public Mass getMass1() {
        checkValid();
        return model.massHandle(model.engineLinkMass(id, true));
    }

    /** @return the handle of the second mass (the same as the first for a plane contact). */
    public Mass getMass2() {
        checkValid();
        return model.massHandle(model.engineLinkMass(id, false));
    }

    /** @return the current distance between the two masses (for a plane contact, the gap to the plane). */
    public double getDistance() {
        checkValid();
        return model.getLinkDistance(model.linkName(id));
    }

    /** @return the distance minus the length parameter (rest length, threshold, radius, offset or limit). */
    public double getElongation() {
        checkValid();
        return model.getLinkElongation(model.linkName(id));
    }

    double stiffness() {
        checkValid();
        return model.getLinkStiffness(model.linkName(id));
    }

    void stiffness(double K) {
        checkValid();
        model.setLinkStiffness(model.linkName(id), K);
    }

    double damping() {
        checkValid();
        return model.getLinkDamping(model.linkName(id));
    }

    void damping(double Z) {
        checkValid();
        model.setLinkDamping(model.linkName(id), Z);
    }

    double length() {
        checkValid();
        return model.getLinkDRest(model.linkName(id));
    }

    void length(double d) {
        checkValid();
        model.setLinkDRest(model.linkName(id), d);
    }
}
