package tactus.internal.edit;

import tactus.engine.Engine;
import tactus.engine.MassKind;
import tactus.Ground3D;
import tactus.internal.model.ModelCore;

/**
 * Removes modules, turns masses into fixed points and clears the model, keeping the directory, the subsets,
 * the contact groups and the divergence state consistent with the engine. Once the model is initialised,
 * every topology edit recompiles the step plan at once, on the editing thread, so that the threads that step
 * the model or exchange with it (audio, haptics) never compile. The caller holds the model's lock.
 */
public final class TopologyEditor {
    private final ModelCore c;
    private final Engine engine;

    public TopologyEditor(ModelCore core) {
        this.c = core;
        this.engine = core.engine;
    }

    /**
     * Compiles the step plan now if the model is initialised, and tells the snapshot writer that the topology
     * changed (it publishes at once when someone reads, else on the next read). While the engine holds topology
     * changes for a plan prepared by an editor thread (realtime stepping), both wait for the install
     * ({@link InstallCommand}).
     */
    public void compileIfRunning() {
        if (c.initialized) {
            engine.compile();
            if (engine.isHoldingTopology()) {
                c.snapshots.topologyEdited(); // the install publishes the new topology
            } else {
                c.snapshots.topologyChanged();
            }
        }
    }

    public void removeLink(int id) {
        engine.removeLink(id);
        c.subsets.forgetLink(id);
        c.dir.forgetLink(id);
        compileIfRunning();
    }

    public void removeMass(int id) {
        boolean wasDiverged = engine.divergedMass() == id;
        for (int l : c.dir.links.ids()) {
            if (engine.linkMassA(l) == id || engine.linkMassB(l) == id) {
                engine.removeLink(l);
                c.subsets.forgetLink(l);
                c.dir.forgetLink(l);
            }
        }
        engine.removeMass(id);
        c.dir.forgetMass(id);
        c.subsets.forgetMass(id);
        if (wasDiverged) {
            c.watch.clear();
        }
        compileIfRunning();
    }

    /**
     * Turns a mass into a fixed point at its current position; its interactions stay attached. It cannot make a
     * stable model unstable, so it is never refused.
     */
    public Ground3D makeFixed(int id) {
        engine.makeFixed(id);
        Ground3D h = (Ground3D) c.dir.storeMassHandle(c.model, id, MassKind.GROUND3D);
        // no stability check: fixing a mass removes a row and a column of the symmetric form of M^-1(K + 2Z),
        // so by eigenvalue interlacing its largest eigenvalue cannot grow
        compileIfRunning();
        return h;
    }

    /** Removes every mass, interaction, subset, contact group and controller; lets a diverged model run again. */
    public void clear() {
        c.dir.clear();
        engine.clear();
        c.subsets.clear();
        c.clearControllers();
        c.watch.clear();
        compileIfRunning();
    }
}
