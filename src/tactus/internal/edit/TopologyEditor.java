package tactus.internal.edit;

import tactus.engine.Engine;
import tactus.engine.MassKind;
import tactus.internal.model.ModelBase;
import tactus.internal.snapshot.SnapshotWriter;
import tactus.internal.stability.DivergenceWatch;

/**
 * Removes modules, turns masses into fixed points and clears the model, keeping the directory, the subsets,
 * the contact groups and the divergence state consistent with the engine. Once the model is initialised and
 * stepped in realtime ({@code beginRealtimeStepping}), every topology edit recompiles the step plan at once, on
 * the editing thread, so that the threads that step the model or exchange with it (audio, haptics) never
 * compile. Otherwise a thread that steps takes the model's lock, and so waits for an edit anyway: the plan is
 * compiled once, by the next step (or the next read of the plan), however many edits came before it, so that
 * removing k of N modules costs O(k + N), not O(k N). The caller holds the model's lock.
 */
public final class TopologyEditor {
    private final ModelBase c;
    private final SnapshotWriter snapshots;
    private final DivergenceWatch watch;
    /** Set once by ModelCore (the subset book is made after this editor). */
    public SubsetBook subsets;
    private final Engine engine;

    public TopologyEditor(ModelBase core, SnapshotWriter snapshots, DivergenceWatch watch) {
        this.snapshots = snapshots;
        this.watch = watch;
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
        if (c.initialized && c.own == null) {
            snapshots.topologyChanged();   // the plan is compiled by the next step, once for every edit before it
        } else if (c.initialized) {
            engine.compile();
            if (engine.isHoldingTopology()) {
                snapshots.topologyEdited(); // the install publishes the new topology
            } else {
                snapshots.topologyChanged();
            }
        }
    }

    public void removeLink(int id) {
        engine.removeLink(id);
        subsets.forgetLink(id);
        c.dir.forgetLink(id);
        compileIfRunning();
    }

    public void removeMass(int id) {
        boolean wasDiverged = engine.divergedMass() == id;
        for (int l : engine.linksOf(id)) {
            engine.removeLink(l);
            subsets.forgetLink(l);
            c.dir.forgetLink(l);
        }
        engine.removeMass(id);
        c.dir.forgetMass(id);
        subsets.forgetMass(id);
        if (wasDiverged) {
            watch.clear();
        }
        compileIfRunning();
    }

    /**
     * Turns a mass into a fixed point at its current position; its interactions stay attached. It cannot make a
     * stable model unstable, so it is never refused.
     */
    public void makeFixed(int id) {
        engine.makeFixed(id);
        c.dir.retypeMass(id, MassKind.GROUND3D);
        // no stability check: fixing a mass removes a row and a column of the symmetric form of M^-1(K + 2Z),
        // so by eigenvalue interlacing its largest eigenvalue cannot grow
        compileIfRunning();
    }

    /** Removes every mass, interaction, subset, contact group and controller; lets a diverged model run again. */
    public void clear() {
        c.dir.clear();
        engine.clear();
        subsets.clear();
        c.ramps.clear();
        watch.clear();
        compileIfRunning();
    }
}
