package tactus;

/** A mass-type module that integrates forces: it has an inertia and a velocity that can be set. */
public abstract class InertialMass extends Mass {
    InertialMass(PhysicalModel model, int id) {
        super(model, id);
    }

    /** @return the inertia (REAL_UNITS: kg). */
    public double getMass() {
        checkValid();
        return model.getMatMass(model.massName(id));
    }

    /** Sets the inertia, finite and &gt; 0 (REAL_UNITS: kg). */
    public void setMass(double mass) {
        checkValid();
        model.setMassOf("setMass", id, mass);
    }

    /** Sets the velocity in units per second, keeping the position. */
    public void setVelocity(Vect3D vel) {
        checkValid();
        model.setMatVelocity(model.massName(id), vel);
    }
}
