package tactus;

import tactus.engine.Engine;
import tactus.engine.MassKind;

/**
 * Publishes {@link ModelSnapshot}s of the model for the drawing thread: at the end of every
 * {@link PhysicalModel#draw_physics()}, at {@link PhysicalModel#init()}, after topology edits, and while the model
 * is stepped step by step (by an audio or haptic loop) every half display frame of simulated time. The caller
 * holds the model's lock, which makes every publisher the single writer of the exchange.
 */
final class SnapshotWriter {
    private final ModelCore c;
    private final Engine engine;
    final SnapshotExchange exchange = new SnapshotExchange();
    private final double[] tmp = new double[3];
    private long stepsSince;
    /** Per mass index: the engine id and the avatar force sum seen at the last publication, and its step. */
    private int[] lastId = new int[0];
    private double[] lastSum = new double[0];
    private long lastStep = -1;

    SnapshotWriter(ModelCore core) {
        this.c = core;
        this.engine = core.engine;
    }

    /** Counts steps just run and publishes when half a display frame of simulated time has passed. */
    void afterSteps(int n) {
        stepsSince += n;
        if (2L * stepsSince * c.time.displayRate() >= c.time.simRate()) {
            publish();
        }
    }

    /** Copies the current state into the back buffer and hands it to the reader. */
    void publish() {
        stepsSince = 0;
        ModelSnapshot s = exchange.back();
        Directory dir = c.dir;
        int nm = dir.mats.size();
        int nl = dir.links.size();
        s.ensure(nm, nl);
        if (lastId.length < nm) {
            lastId = java.util.Arrays.copyOf(lastId, s.massTypes.length);
            lastSum = java.util.Arrays.copyOf(lastSum, 3 * s.massTypes.length);
        }
        boolean motion = exchange.motion;
        long step = engine.stepCount();
        long since = lastStep < 0 ? 0 : step - lastStep;
        UnitScale u = c.units();
        for (int i = 0; i < nm; i++) {
            int id = dir.mats.idAt(i);
            int q = 3 * i;
            engine.position(id, tmp);
            s.pos[q] = tmp[0];
            s.pos[q + 1] = tmp[1];
            s.pos[q + 2] = tmp[2];
            MassKind kind = engine.massKind(id);
            s.massTypes[i] = ModuleTypes.of(kind);
            if (!motion && kind != MassKind.HAPTIC_INPUT3D) {
                // velocities and forces only on request: they cost about as much again as the positions
                s.vel[q] = 0;
                s.vel[q + 1] = 0;
                s.vel[q + 2] = 0;
                s.force[q] = 0;
                s.force[q + 1] = 0;
                s.force[q + 2] = 0;
                continue;
            }
            engine.displacement(id, tmp);
            s.vel[q] = u.velocityOut(tmp[0]);
            s.vel[q + 1] = u.velocityOut(tmp[1]);
            s.vel[q + 2] = u.velocityOut(tmp[2]);
            // After a step the buffer holds the interaction forces for the next one. An avatar's buffer sums them
            // until someone takes it: the mean per step is taken over the steps since the last publication when
            // nobody took it in between, else over the steps since it was taken.
            engine.force(id, tmp);
            double fx = tmp[0];
            double fy = tmp[1];
            double fz = tmp[2];
            double per = 1;
            if (kind == MassKind.HAPTIC_INPUT3D) {
                long taken = engine.stepsSinceTake(id);
                if (since > 0 && taken > since && lastId[i] == id) {
                    tmp[0] = fx - lastSum[q];
                    tmp[1] = fy - lastSum[q + 1];
                    tmp[2] = fz - lastSum[q + 2];
                    per = 1.0 / since;
                } else {
                    per = taken > 1 ? 1.0 / taken : 1;
                }
            } else if (kind.isFixed() || kind == MassKind.POS_INPUT3D) {
                per = 0;
            }
            lastId[i] = id;
            lastSum[q] = fx;
            lastSum[q + 1] = fy;
            lastSum[q + 2] = fz;
            s.force[q] = per * u.forceOut(tmp[0]);
            s.force[q + 1] = per * u.forceOut(tmp[1]);
            s.force[q + 2] = per * u.forceOut(tmp[2]);
        }
        for (int l = 0; l < nl; l++) {
            int id = dir.links.idAt(l);
            s.ends[2 * l] = dir.mats.indexOf(engine.linkMassA(id));
            s.ends[2 * l + 1] = dir.mats.indexOf(engine.linkMassB(id));
            s.elongation[l] = engine.linkDistance(id) - engine.linkLength(id);
            s.linkTypes[l] = ModuleTypes.of(engine.linkKind(id));
        }
        s.masses = nm;
        s.links = nl;
        s.motion = motion;
        s.step = step;
        lastStep = step;
        exchange.publish();
    }
}
