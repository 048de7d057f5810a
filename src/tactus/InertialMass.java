package tactus;

import tactus.internal.calls.ModuleCalls.MassParam;


/** A mass-type module that integrates forces: it has an inertia and a velocity that can be set. */
public abstract class InertialMass extends Mass {
    InertialMass(ModuleHandles handles, int id, int stamp) {
        super(handles, id, stamp);
    }

    /** {@return the inertia (REAL_UNITS: kg)} */
    public double getMass() {
        checkValid();
        return calls.massParam(id, stamp, MassParam.MASS);
    }

    /** Sets the inertia, finite and &gt; 0 (REAL_UNITS: kg). */
    public void setMass(double mass) {
        checkValid();
        calls.setMassParam(id, stamp, MassParam.MASS, mass);
    }

    /** Sets the velocity in units per second, keeping the position. */
    public void setVelocity(Vect3D vel) {
        checkVector("setVelocity", "vel", vel);
        calls.setVelocity(id, stamp, vel);
    }
}
