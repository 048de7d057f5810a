package tactus;

import tactus.internal.calls.ModuleCalls.MassParam;


/**
 * A mass tied to its rest position by an internal spring and damper (Osc3D, Osc1D). Parameter
 * changes take effect at the next step.
 */
public abstract class Oscillator extends InertialMass {
    Oscillator(ModuleHandles handles, int id, int stamp) {
        super(handles, id, stamp);
    }

    /** {@return the internal stiffness (REAL_UNITS: N/m)} */
    public double getStiffness() {
        checkValid();
        return calls.massParam(id, stamp, MassParam.STIFFNESS);
    }

    /** Sets the internal stiffness (REAL_UNITS: N/m). */
    public void setStiffness(double K) {
        checkFinite("setStiffness", "K", K);
        calls.setMassParam(id, stamp, MassParam.STIFFNESS, K);
    }

    /** {@return the internal damping (REAL_UNITS: N·s/m)} */
    public double getDamping() {
        checkValid();
        return calls.massParam(id, stamp, MassParam.DAMPING);
    }

    /** Sets the internal damping (REAL_UNITS: N·s/m). */
    public void setDamping(double Z) {
        checkFinite("setDamping", "Z", Z);
        calls.setMassParam(id, stamp, MassParam.DAMPING, Z);
    }
}
