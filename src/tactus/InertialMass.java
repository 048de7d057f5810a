package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A mass-type module that integrates forces: it has an inertia and a velocity that can be set. */
public abstract class InertialMass extends Mass {
    InertialMass(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }

    /** @return the inertia (REAL_UNITS: kg). */
    public double getMass() {
        enter();
        try {
            return core.params.mass("getMass", id);
        } finally {
            exit();
        }
    }

    /** Sets the inertia, finite and &gt; 0 (REAL_UNITS: kg). */
    public void setMass(double mass) {
        enter();
        try {
            core.params.setMass("setMass", id, mass);
        } finally {
            exit();
        }
    }

    /** Sets the velocity in units per second, keeping the position. */
    public void setVelocity(Vect3D vel) {
        checkVector("setVelocity", "vel", vel);
        enter();
        try {
            core.state.setVelocity("setVelocity", id, vel);
        } finally {
            exit();
        }
    }
}
