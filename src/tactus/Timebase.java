package tactus;

import tactus.engine.Engine;
import tactus.engine.LinkKind;

/**
 * The model's clock and global medium: simulation and display rates, the fractional step carried between
 * frames, the unit conversion at the current rate, and gravity and air friction as the user gave them. A rate
 * change in REAL_UNITS re-derives every per-step coefficient (links, oscillators, contact groups, attractors,
 * medium) so that the model keeps describing the same physical system. The caller holds the model's lock.
 */
final class Timebase {
    private final Engine engine;
    private final Directory dir;
    final UnitScale units;
    private int simRate;
    private int dispRate;
    /** Fractional step carried between frames, in units of 1/dispRate steps (exact integer arithmetic). */
    private long residue;
    private double gravity;
    private final Vect3D gravityDir = new Vect3D(0, 0, 1);
    private double friction;

    Timebase(Engine engine, Directory dir, paramSystem system, int simRate, int dispRate) {
        this.engine = engine;
        this.dir = dir;
        this.simRate = simRate;
        this.dispRate = dispRate;
        this.units = new UnitScale(system, simRate);
    }

    int simRate() {
        return simRate;
    }

    int displayRate() {
        return dispRate;
    }

    void setDisplayRate(int rate) {
        dispRate = rate;
        residue = 0;
    }

    /** @return the number of steps of the next display frame, carrying the fractional remainder. */
    int stepsForFrame() {
        long total = simRate + residue;
        residue = total % dispRate;
        return (int) (total / dispRate);
    }

    /**
     * Moves the model to a new simulation rate; in REAL_UNITS rescales every coefficient and the state's
     * per-step velocities and pending forces.
     *
     * @param groupIds the engine ids of the live contact groups
     */
    void setSimRate(int rate, int[] groupIds) {
        double ratio = (double) simRate / rate;
        simRate = rate;
        residue = 0;
        if (units.isReal() && ratio != 1.0) {
            rescaleCoefficients(ratio, groupIds);
        }
        units.setRate(rate);
        applyMedium();
    }

    private void rescaleCoefficients(double ratio, int[] groupIds) {
        double r2 = ratio * ratio;
        for (int id : dir.mats.ids()) {
            if (engine.massKind(id).isOscillator()) {
                engine.setOscillator(id, engine.oscStiffness(id) * r2, engine.oscDamping(id) * ratio);
            }
        }
        for (int id : dir.links.ids()) {
            engine.setLinkParams(id, engine.linkStiffness(id) * r2, engine.linkDamping(id) * ratio,
                    engine.linkLength(id));
            if (engine.linkKind(id) == LinkKind.ATTRACTOR3D) {
                engine.setLinkAux(id, engine.linkAux(id) * r2);
            }
        }
        for (int gid : groupIds) {
            double[] p = engine.contactGroupParams(gid);
            engine.setContactGroupParams(gid, p[0], p[1] * r2, p[2] * ratio);
        }
        engine.rescaleTime(ratio);
    }

    // ---------------------------------------------------------------- medium

    double gravity() {
        return gravity;
    }

    void setGravity(double magnitude) {
        gravity = magnitude;
        applyMedium();
    }

    Vect3D gravityDirection(Vect3D out) {
        return out.set(gravityDir);
    }

    /** Sets the "up" direction from a validated, non-zero vector; it is normalised. */
    void setGravityDirection(double x, double y, double z) {
        double big = Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
        double ux = x / big, uy = y / big, uz = z / big;
        double n = Math.sqrt(ux * ux + uy * uy + uz * uz);
        gravityDir.set(ux / n, uy / n, uz / n);
        applyMedium();
    }

    double friction() {
        return friction;
    }

    void setFriction(double f) {
        friction = f;
        applyMedium();
    }

    private void applyMedium() {
        double g = units.accelerationIn(gravity);
        engine.setGravity(-g * gravityDir.x, -g * gravityDir.y, -g * gravityDir.z);
        engine.setFriction(units.dampingIn(friction));
    }
}
