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
        model.enter(this);
        try {
            return model.core.dir.linkName(id);
        } finally {
            model.exit();
        }
    }

    @Override
    public String getType() {
        checkValid();
        return getClass().getSimpleName();
    }

    /** @return the handle of the first mass. */
    public Mass getMass1() {
        model.enter(this);
        try {
            return model.core.dir.massHandle(model.core.engine.linkMassA(id));
        } finally {
            model.exit();
        }
    }

    /** @return the handle of the second mass (the same as the first for a plane contact). */
    public Mass getMass2() {
        model.enter(this);
        try {
            return model.core.dir.massHandle(model.core.engine.linkMassB(id));
        } finally {
            model.exit();
        }
    }

    /** @return the current distance between the two masses (for a plane contact, the gap to the plane). */
    public double getDistance() {
        model.enter(this);
        try {
            return model.core.params.linkDistance(id);
        } finally {
            model.exit();
        }
    }

    /** @return the distance minus the length parameter (rest length, threshold, radius, offset or limit). */
    public double getElongation() {
        model.enter(this);
        try {
            return model.core.params.linkElongation(id);
        } finally {
            model.exit();
        }
    }

    double stiffness() {
        model.enter(this);
        try {
            return model.core.params.linkStiffness(id);
        } finally {
            model.exit();
        }
    }

    void stiffness(double K) {
        checkFinite("setStiffness", "K", K);
        model.enter(this);
        try {
            model.core.params.setLink("setStiffness", id, K, Double.NaN, Double.NaN);
        } finally {
            model.exit();
        }
    }

    double damping() {
        model.enter(this);
        try {
            return model.core.params.linkDamping(id);
        } finally {
            model.exit();
        }
    }

    void damping(double Z) {
        checkFinite("setDamping", "Z", Z);
        model.enter(this);
        try {
            model.core.params.setLink("setDamping", id, Double.NaN, Z, Double.NaN);
        } finally {
            model.exit();
        }
    }

    double length() {
        model.enter(this);
        try {
            return model.core.params.linkLength(id);
        } finally {
            model.exit();
        }
    }

    void length(String op, double d) {
        checkFinite(op, "d", d);
        model.enter(this);
        try {
            model.core.params.setLink(op, id, Double.NaN, Double.NaN, d);
        } finally {
            model.exit();
        }
    }
}
