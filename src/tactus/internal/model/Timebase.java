package tactus.internal.model;

import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * The model's clock and global medium: simulation and display rates, the fractional step carried between
 * frames, the unit conversion at the current rate, and gravity and air friction as the user gave them. A rate
 * change in REAL_UNITS re-derives every per-step coefficient (links, oscillators, contact groups, attractors,
 * medium) so that the model keeps describing the same physical system. The caller holds the model's lock.
 */
public final class Timebase {
    private final Engine engine;
    private final Directory dir;
    public final UnitScale units;
    private int simRate;
    private int dispRate;
    /** Fractional step carried between frames, in units of 1/dispRate steps (exact integer arithmetic). */
    private long residue;
    private double gravity;
    private final Vect3D gravityDir = new Vect3D(0, 0, 1);
    private double friction;
    /** Where the current thread's engine writes go (set once by ModelBase), for the writes of the medium. */
    public java.util.function.Supplier<EngineWrites> writes;

    public Timebase(Engine engine, Directory dir, paramSystem system, int simRate, int dispRate) {
        this.engine = engine;
        this.dir = dir;
        this.simRate = simRate;
        this.dispRate = dispRate;
        this.units = new UnitScale(system, simRate);
    }

    public int simRate() {
        return simRate;
    }

    public int displayRate() {
        return dispRate;
    }

    public void setDisplayRate(int rate) {
        dispRate = rate;
        residue = 0;
    }

    /** @return the number of steps of the next display frame, carrying the fractional remainder. */
    public int stepsForFrame() {
        long total = simRate + residue;
        residue = total % dispRate;
        return (int) (total / dispRate);
    }

    /**
     * Moves the model to a new simulation rate. In REAL_UNITS every per-step coefficient is re-derived first and
     * checked by the stability guard (under THROW a refused rate restores every coefficient bit for bit); only
     * then are the state's per-step velocities and pending forces rescaled.
     *
     * @param groupIds the engine ids of the live contact groups
     */
    public void setSimRate(int rate, int[] groupIds, java.util.function.Consumer<Runnable> check) {
        int old = simRate;
        double ratio = (double) old / rate;
        boolean rescale = units.isReal() && ratio != 1.0;
        Runnable restore = rescale ? rescaleCoefficients(ratio, groupIds) : () -> { };
        applyRate(rate);
        check.accept(() -> {
            restore.run();
            applyRate(old);
        });
        residue = 0;
        if (rescale) {
            engine.rescaleTime(ratio);
        }
    }

    private void applyRate(int rate) {
        simRate = rate;
        units.setRate(rate);
        applyMedium();
    }

    /** Rescales every per-step coefficient for a rate change; returns the exact undo. */
    private Runnable rescaleCoefficients(double ratio, int[] groupIds) {
        double r2 = ratio * ratio;
        int[] oscs = java.util.Arrays.stream(dir.mats.ids()).filter(id -> engine.massKind(id).isOscillator()).toArray();
        int[] links = dir.links.ids();
        double[] saved = new double[2 * oscs.length + 3 * links.length + 3 * groupIds.length];
        int w = 0;
        for (int id : oscs) {
            saved[w++] = engine.oscStiffness(id);
            saved[w++] = engine.oscDamping(id);
            engine.setOscillator(id, engine.oscStiffness(id) * r2, engine.oscDamping(id) * ratio);
        }
        for (int id : links) {
            saved[w++] = engine.linkStiffness(id);
            saved[w++] = engine.linkDamping(id);
            saved[w++] = engine.linkKind(id) == LinkKind.ATTRACTOR3D ? engine.attraction(id) : 0;
            engine.setLinkParams(id, engine.linkStiffness(id) * r2, engine.linkDamping(id) * ratio,
                    engine.linkLength(id));
            if (engine.linkKind(id) == LinkKind.ATTRACTOR3D) {
                engine.setAttraction(id, engine.attraction(id) * r2);
            }
        }
        java.util.List<double[]> auxSaved = new java.util.ArrayList<>();
        for (int id : links) {
            LinkKind kind = engine.linkKind(id);
            for (int i = 0; i < kind.auxCount(); i++) {
                double scale = scaleFor(kind.auxUnit(i), ratio);
                if (scale != 1) {
                    double v = engine.linkAux(id, i);
                    auxSaved.add(new double[] {id, i, v});
                    engine.setLinkAux(id, i, v * scale);
                }
            }
        }
        for (int gid : groupIds) {
            double[] p = engine.contactGroupParams(gid);
            saved[w++] = p[0];
            saved[w++] = p[1];
            saved[w++] = p[2];
            engine.setContactGroupParams(gid, p[0], p[1] * r2, p[2] * ratio);
        }
        return () -> {
            for (double[] a : auxSaved) {
                engine.setLinkAux((int) a[0], (int) a[1], a[2]);
            }
            int r = 0;
            for (int id : oscs) {
                engine.setOscillator(id, saved[r], saved[r + 1]);
                r += 2;
            }
            for (int id : links) {
                engine.setLinkParams(id, saved[r], saved[r + 1], engine.linkLength(id));
                if (engine.linkKind(id) == LinkKind.ATTRACTOR3D) {
                    engine.setAttraction(id, saved[r + 2]);
                }
                r += 3;
            }
            for (int gid : groupIds) {
                engine.setContactGroupParams(gid, saved[r], saved[r + 1], saved[r + 2]);
                r += 3;
            }
        };
    }

    /** @return the factor a per-step parameter of unit class u takes when the step lengthens by {@code ratio}. */
    private static double scaleFor(LinkKind.ParamUnit u, double ratio) {
        switch (u) {
            case STIFFNESS:
                return ratio * ratio;
            case DAMPING:
            case VELOCITY:
                return ratio;
            default:
                return 1;
        }
    }

    /**
     * Switches the unit system of every later call. The model itself is unchanged: gravity and friction, kept
     * here in the user's units, are re-expressed in the new system.
     */
    public void setParamSystem(paramSystem system) {
        double g = units.accelerationIn(gravity);
        double f = units.dampingIn(friction);
        units.setSystem(system);
        gravity = units.accelerationOut(g);
        friction = units.dampingOut(f);
    }

    // ---------------------------------------------------------------- medium

    public double gravity() {
        return gravity;
    }

    public void setGravity(double magnitude) {
        gravity = magnitude;
        applyMedium();
    }

    public Vect3D gravityDirection(Vect3D out) {
        return out.set(gravityDir);
    }

    /** Sets the "up" direction from a validated, non-zero vector; it is normalised. */
    public void setGravityDirection(double x, double y, double z) {
        double big = Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
        double ux = x / big, uy = y / big, uz = z / big;
        double n = Math.sqrt(ux * ux + uy * uy + uz * uz);
        gravityDir.set(ux / n, uy / n, uz / n);
        applyMedium();
    }

    public double friction() {
        return friction;
    }

    public void setFriction(double f) {
        friction = f;
        applyMedium();
    }

    private void applyMedium() {
        double g = units.accelerationIn(gravity);
        EngineWrites w = writes != null ? writes.get() : EngineWrites.direct(engine);
        w.setMedium(-g * gravityDir.x, -g * gravityDir.y, -g * gravityDir.z, units.dampingIn(friction));
    }
}
