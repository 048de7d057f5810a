package tactus;

/** A mass-type module that integrates forces: it has an inertia and a velocity that can be set. */
public abstract class InertialMass extends Mass {
    InertialMass(PhysicalModel model, int id) {
        super(model, id);
    }

    /** @return the inertia (REAL_UNITS: kg). */
    public double getMass() {
        model.enter(this);
        try {
            return model.core.params.mass("getMass", id);
        } finally {
            model.exit();
        }
    }

    /** Sets the inertia, finite and &gt; 0 (REAL_UNITS: kg). */
    public void setMass(double mass) {
        model.enter(this);
        try {
            model.core.params.setMass("setMass", id, mass);
        } finally {
            model.exit();
        }
    }

    /** Sets the velocity in units per second, keeping the position. */
    public void setVelocity(Vect3D vel) {
        checkVector("setVelocity", "vel", vel);
        model.enter(this);
        try {
            model.core.state.setVelocity("setVelocity", id, vel);
        } finally {
            model.exit();
        }
    }
}
