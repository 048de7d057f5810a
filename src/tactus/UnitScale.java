package tactus;

import tactus.engine.Units;

/**
 * Converts parameters between a model's unit system and the engine's per-step units at the
 * model's current simulation rate. In {@link paramSystem#ALGO_UNITS} every conversion is the
 * identity except velocities, which are always given in units per second.
 */
final class UnitScale {
    private boolean real;
    private double fs;

    UnitScale(paramSystem system, double fs) {
        this.real = system == paramSystem.REAL_UNITS;
        this.fs = fs;
    }

    boolean isReal() {
        return real;
    }

    void setSystem(paramSystem system) {
        real = system == paramSystem.REAL_UNITS;
    }

    void setRate(double fs) {
        this.fs = fs;
    }

    double stiffnessIn(double k) {
        return real ? Units.stiffnessToAlgo(k, fs) : k;
    }

    double stiffnessOut(double k) {
        return real ? Units.stiffnessToReal(k, fs) : k;
    }

    double dampingIn(double z) {
        return real ? Units.dampingToAlgo(z, fs) : z;
    }

    double dampingOut(double z) {
        return real ? Units.dampingToReal(z, fs) : z;
    }

    double accelerationIn(double g) {
        return real ? Units.accelerationToAlgo(g, fs) : g;
    }

    double accelerationOut(double g) {
        return real ? Units.accelerationToReal(g, fs) : g;
    }

    /** Forces, attraction factors and energies share the fs^2 scale. */
    double forceIn(double f) {
        return real ? Units.forceToAlgo(f, fs) : f;
    }

    double forceOut(double f) {
        return real ? Units.forceToReal(f, fs) : f;
    }

    double velocityIn(double v) {
        return Units.velocityToStep(v, fs);
    }

    double velocityOut(double v) {
        return Units.velocityToSecond(v, fs);
    }
}
