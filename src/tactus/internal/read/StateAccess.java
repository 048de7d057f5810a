package tactus.internal.read;

import tactus.engine.EnergyMeter;
import tactus.engine.Engine;
import tactus.engine.MassKind;
import tactus.engine.StepPlan;
import tactus.Vect3D;
import tactus.internal.model.Check;
import tactus.internal.model.PaperLeniency;
import tactus.internal.model.UnitScale;
import tactus.internal.edit.ParamEditor;
import tactus.internal.edit.TopologyEditor;
import tactus.internal.model.ModelBase;
import tactus.internal.model.RealtimeMode;

/**
 * Reads and writes the simulated state in the model's units: positions, velocities (always in units per
 * second), forces, hand-set positions and velocities, force impulses, the haptic avatar's target and
 * accumulated force, and the energies. Nothing here allocates except the facade getters that return a new
 * {@link Vect3D}. The caller holds the model's lock, or is the realtime owner (which has a scratch vector of its
 * own). The reads never write the engine.
 */
public final class StateAccess {
    private final ModelBase c;
    private final ParamEditor params;
    private final TopologyEditor topology;
    private final Engine engine;
    /** Scratch vectors, one for the realtime owner and one for lock holders. */
    private final RoleScratch scratch;

    public StateAccess(ModelBase core, ParamEditor params, TopologyEditor topology) {
        this.params = params;
        this.topology = topology;
        this.c = core;
        this.engine = core.engine;
        this.scratch = new RoleScratch(core);
    }

    public Vect3D position(int id, Vect3D out) {
        double[] tmp = scratch.get();
        engine.position(id, tmp);
        return out.set(tmp[0], tmp[1], tmp[2]);
    }

    public Vect3D velocity(int id, Vect3D out) {
        double[] tmp = scratch.get();
        engine.displacement(id, tmp);
        UnitScale u = c.units();
        return out.set(u.velocityOut(tmp[0]), u.velocityOut(tmp[1]), u.velocityOut(tmp[2]));
    }

    public Vect3D force(int id, Vect3D out) {
        double[] tmp = scratch.get();
        engine.force(id, tmp);
        UnitScale u = c.units();
        return out.set(u.forceOut(tmp[0]), u.forceOut(tmp[1]), u.forceOut(tmp[2]));
    }

    /**
     * Whether a position move keeps the moved mass's link history, as the paper's engine did (see
     * {@link PhysicalModel#setMoveKeepsLinkHistory}); read by the thread that records the move.
     */
    public volatile boolean moveKeepsLinkHistory;

    /**
     * Moves a mass to a validated position with zero velocity; its links forget their previous distance, unless
     * {@link #moveKeepsLinkHistory}.
     */
    public void setPosition(int id, Vect3D pos) {
        if (moveKeepsLinkHistory) {
            c.writes().setPositionKeepingLinkHistory(id, pos.x, pos.y, pos.z);
        } else {
            c.writes().setPosition(id, pos.x, pos.y, pos.z);
        }
    }

    /** Sets the velocity (units per second) of an inertial mass, keeping its position. */
    public void setVelocity(String op, int id, Vect3D vel) {
        params.requireInertial(op, id);
        UnitScale u = c.units();
        c.writes().setVelocity(id, u.velocityIn(vel.x), u.velocityIn(vel.y), u.velocityIn(vel.z));
    }

    /** Adds a force (model units) to a mass for the next step only. */
    public void addImpulse(int id, double fx, double fy, double fz) {
        UnitScale u = c.units();
        c.writes().addForce(id, u.forceIn(fx), u.forceIn(fy), u.forceIn(fz));
    }

    /** Puts a free mass under velocity control at (vx, vy, vz) units per second. */
    public void driveVelocity(String op, int id, double vx, double vy, double vz) {
        MassKind k = engine.massKind(id);
        if (!k.isDrivable()) {
            throw Check.fail(op, c.dir.massName(id), "only free masses (Mass3D, Mass3DSimple, Mass2DPlane, Mass1D) "
                    + "can be put under velocity control, this is a " + k.label());
        }
        UnitScale u = c.units();
        engine.driveVelocity(id, u.velocityIn(vx), u.velocityIn(vy), u.velocityIn(vz));
        topology.compileIfRunning();
    }

    /** Releases a mass from velocity control (nothing happens if it is not under control). */
    public void stopDriving(int id) {
        engine.stopDriving(id);
        topology.compileIfRunning();
    }

    public void requireInput(String op, int id) {
        MassKind k = engine.massKind(id);
        if (!k.isInput()) {
            throw Check.fail(op, c.dir.massName(id), "not an input module, this is a " + k.label());
        }
    }

    /**
     * @return true when the mass is an input module; otherwise, for the paper's haptic calls, false after one warning
     *     (the paper's engine printed a line and did nothing), or the exception of {@link #requireInput} in strict mode
     */
    public boolean paperIsInput(String op, int id, String skipped) {
        return c.paperMassIs(MassKind::isInput, PaperLeniency.Kind.NOT_AN_INPUT, op, id, "not an input module",
                skipped);
    }

    /** Sets the target that an input module follows through its EWMA. */
    public void setInputTarget(int id, double x, double y, double z) {
        c.writes().setInputTarget(id, x, y, z);
    }

    /**
     * The avatar force for whichever thread asks: the engine's accumulator on a model that is not stepped in
     * realtime; on one that is, another thread reads through a {@link ForceTaps tap}, and the stepping thread reads
     * the tap too once one exists (the tap collects the engine's accumulator after each stepping call), plus
     * whatever the engine gathered since. Each avatar's force must be read from one thread only.
     */
    public Vect3D takeAvatarForce(int id, Vect3D out) {
        takeAvatarForceCounted(id, out);
        return out;
    }

    /**
     * As {@link #takeAvatarForce}, and returns how many steps the force sums over, read together with it (the
     * model units of force are converted to the user's units in {@code out}).
     */
    public long takeAvatarForceCounted(int id, Vect3D out) {
        double[] tmp = scratch.get();
        RealtimeMode o = c.own;
        long n;
        double x;
        double y;
        double z;
        if (o != null && !o.isOwnerThread()) {
            n = o.takeTappedForce(id, tmp, true);
            x = tmp[0];
            y = tmp[1];
            z = tmp[2];
        } else {
            long tapped = o == null ? -1 : o.takeTappedForce(id, tmp, false);
            if (tapped >= 0) {
                n = tapped;
                x = tmp[0];
                y = tmp[1];
                z = tmp[2];
            } else {
                n = 0;
                x = 0;
                y = 0;
                z = 0;
            }
            n += engine.takeForce(id, tmp);
            x += tmp[0];
            y += tmp[1];
            z += tmp[2];
        }
        if (engine.massKind(id) == MassKind.POS_INPUT3D) {
            out.set(0, 0, 0);
            return n;
        }
        UnitScale u = c.units();
        out.set(u.forceOut(x), u.forceOut(y), u.forceOut(z));
        return n;
    }

    /**
     * @return the plan the energies read (they only read it, and a contact group's share never rebuilds the group's
     *     neighbour list): on another thread than a realtime owner, the live plan as it is (never compiled there);
     *     otherwise {@link Engine#planForReading()}, which compiles only a model with no current plan
     */
    private StepPlan planToRead() {
        RealtimeMode o = c.own;
        if (o != null && !o.isOwnerThread()) {
            StepPlan live = engine.livePlan();
            if (live != null) {
                return live;
            }
        }
        return engine.planForReading();
    }

    public double kineticEnergy() {
        return c.units().forceOut(EnergyMeter.kinetic(planToRead()));
    }

    public double potentialEnergy() {
        return c.units().forceOut(EnergyMeter.potential(planToRead()));
    }

    public double totalEnergy() {
        StepPlan p = planToRead();
        return c.units().forceOut(EnergyMeter.kinetic(p) + EnergyMeter.potential(p));
    }
}
