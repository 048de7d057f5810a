package tactus.internal.model;

import tactus.engine.LinkKind;
import tactus.engine.Units;
import tactus.paramSystem;

/**
 * Converts parameters between a model's unit system and the engine's per-step units at the
 * model's current simulation rate. In {@link paramSystem#ALGO_UNITS} every conversion is the
 * identity except velocities, which are always given in units per second.
 */
public final class UnitScale {
    private boolean real;
    private double fs;

    public UnitScale(paramSystem system, double fs) {
        this.real = system == paramSystem.REAL_UNITS;
        this.fs = fs;
    }

    public boolean isReal() {
        return real;
    }

    public void setSystem(paramSystem system) {
        real = system == paramSystem.REAL_UNITS;
    }

    public void setRate(double fs) {
        this.fs = fs;
    }

    public double stiffnessIn(double k) {
        return real ? Units.stiffnessToAlgo(k, fs) : k;
    }

    public double stiffnessOut(double k) {
        return real ? Units.stiffnessToReal(k, fs) : k;
    }

    public double dampingIn(double z) {
        return real ? Units.dampingToAlgo(z, fs) : z;
    }

    public double dampingOut(double z) {
        return real ? Units.dampingToReal(z, fs) : z;
    }

    public double accelerationIn(double g) {
        return real ? Units.accelerationToAlgo(g, fs) : g;
    }

    public double accelerationOut(double g) {
        return real ? Units.accelerationToReal(g, fs) : g;
    }

    /** Forces, attraction factors and energies share the fs^2 scale. */
    public double forceIn(double f) {
        return real ? Units.forceToAlgo(f, fs) : f;
    }

    public double forceOut(double f) {
        return real ? Units.forceToReal(f, fs) : f;
    }

    public double velocityIn(double v) {
        return Units.velocityToStep(v, fs);
    }

    public double velocityOut(double v) {
        return Units.velocityToSecond(v, fs);
    }

    /** Converts a parameter of unit class {@code u} from the model's units to per-step units. */
    public double paramIn(LinkKind.ParamUnit u, double v) {
        if (!real) {
            return v;
        }
        switch (u) {
            case STIFFNESS:
                return Units.stiffnessToAlgo(v, fs);
            case DAMPING:
                return Units.dampingToAlgo(v, fs);
            case VELOCITY:
                return Units.velocityToStep(v, fs);
            default:
                return v;
        }
    }

    /** Converts a parameter of unit class {@code u} from per-step units to the model's units. */
    public double paramOut(LinkKind.ParamUnit u, double v) {
        if (!real) {
            return v;
        }
        switch (u) {
            case STIFFNESS:
                return Units.stiffnessToReal(v, fs);
            case DAMPING:
                return Units.dampingToReal(v, fs);
            case VELOCITY:
                return Units.velocityToSecond(v, fs);
            default:
                return v;
        }
    }
}
