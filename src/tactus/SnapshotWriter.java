package tactus;

import tactus.engine.Engine;

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
        for (int i = 0; i < nm; i++) {
            int id = dir.mats.idAt(i);
            engine.position(id, tmp);
            s.pos[3 * i] = tmp[0];
            s.pos[3 * i + 1] = tmp[1];
            s.pos[3 * i + 2] = tmp[2];
            s.massTypes[i] = ModuleTypes.of(engine.massKind(id));
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
        s.step = engine.stepCount();
        exchange.publish();
    }
}
