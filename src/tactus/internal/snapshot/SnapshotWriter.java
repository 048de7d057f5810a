package tactus.internal.snapshot;

import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.internal.model.Directory;
import tactus.internal.model.ModelBase;
import tactus.internal.model.ModuleTypes;
import tactus.internal.model.UnitScale;
import tactus.linkModuleType;
import tactus.matModuleType;

/**
 * Publishes {@link ModelSnapshot}s of the model for a drawing thread, on demand. Every publisher holds the model's
 * lock (locked mode) or the realtime owner's gate, which makes it the single writer of the exchange.
 *
 * <p>When: nothing is copied until a reader has called {@link PhysicalModel#getSnapshot()} ({@link #request()}).
 * In locked mode the reader publishes itself, holding the lock ({@link #publishForReader()}), when it finds the lock
 * free; a read that finds it busy is served by the stepping thread after the step that ends the current display
 * frame of simulated time. In realtime mode the owner publishes at most once per display frame of simulated time
 * (at the end of a frame of steps) while the reader keeps calling, and {@link #KEEP_FRAMES} frames more; then it
 * stops until the next call, and its next stepping call publishes. A topology change (and {@code init()}) is
 * published at once when a reader has ever read or the model is stepped in realtime; otherwise it marks the copy
 * dirty, and the next read publishes it.
 *
 * <p>What: every mass's position every time; velocities and forces on request; interactions only while the reader
 * asks for them ({@link ModelSnapshot#requestLinks}), and then nothing per interaction unless something changed:
 * their ends, types and shapes are computed once per topology version and copied into each buffer once, their
 * length parameters (and plane positions) are copied into a buffer only when one was set since it last copied them
 * ({@link Engine#linkParameterEdits()}), and the elongation is computed by the reader from the copied positions.
 */
public final class SnapshotWriter {
    /** Frames of simulated time that the model keeps publishing after the reader's last call. */
    public static final int KEEP_FRAMES = 4;
    /** Link shapes, for the reader's elongation: distance in 3D, along z (1D), or to a plane on axis 0, 1, 2. */
    public static final int SHAPE_3D = 0, SHAPE_1D = 1, SHAPE_PLANE = 2;

    private final ModelBase c;
    private final Engine engine;
    public final SnapshotExchange exchange = new SnapshotExchange();
    private final double[] tmp = new double[3];

    // ---- the reader's side (written by the thread that calls getSnapshot)
    /** Calls of {@link #request()} so far. */
    private volatile long reads;

    // ---- the writer's side (written under the model's lock or the owner's gate)
    /** A topology change (or init) is not published yet, and nobody has read since: the reader publishes it. */
    private volatile boolean dirty;
    private long seenReads;
    private int quietFrames = KEEP_FRAMES;
    private long stepsSince;
    private boolean frameDeferred;
    private long lastStep = -1;
    private boolean lastMotion;
    private boolean lastLinks;
    private long lastEdits = -1;
    /** Topology version: bumped by every published topology change; the caches below follow it. */
    private int version;
    private int massCacheVersion = -1;
    private int linkCacheVersion = -1;
    private int massCount = -1;
    /** Bumped by every rebuild of a cache: a buffer copies the cache when its stamp differs. */
    private int massStamp;
    private int linkStamp;
    private int linkCount = -1;
    private int[] massIds = new int[0];
    private MassKind[] massKinds = new MassKind[0];
    private matModuleType[] massTypes = new matModuleType[0];
    /** Mass indices of the haptic avatars (their force is copied even without a request for motion). */
    private int[] avatars = new int[0];
    private int avatarCount;
    private int[] linkIds = new int[0];
    private int[] ends = new int[0];
    private int[] shapes = new int[0];
    private linkModuleType[] linkTypes = new linkModuleType[0];
    private int[] planeLinks = new int[0];
    private int planeCount;
    /** Per mass index: the engine id and the avatar force sum seen at the last publication. */
    private int[] lastId = new int[0];
    private double[] lastSum = new double[0];

    // ---- counters for tests and measurements (written by the writer)
    public long publishes;
    public long massesCopied;
    public long linksCopied;
    public long linkWalks;

    public SnapshotWriter(ModelBase core) {
        this.c = core;
        this.engine = core.engine;
    }

    // ================================================================ the reader's side

    /** The reader's call (from {@link PhysicalModel#getSnapshot()}): asks the writer to keep publishing. */
    public void request() {
        reads = reads + 1; // one reading thread by contract; a lost increment still changes the value
    }

    /** @return true when a topology change is not published yet: the reader waits for the lock to publish it. */
    public boolean dirty() {
        return dirty;
    }

    /**
     * The reader, holding the lock in locked mode, publishes the current state unless the newest copy already shows
     * it (same step, topology, link length parameters and requests; a position set without a step since shows at
     * the next step, as it always did); the writer then stays quiet until a read finds the lock busy.
     */
    public void publishForReader() {
        if (!c.initialized) {
            return;
        }
        if (dirty || engine.stepCount() != lastStep || lastMotion != exchange.motion
                || lastLinks != exchange.links || (lastLinks && engine.linkParameterEdits() != lastEdits)) {
            publish();
        }
        seenReads = reads;
        quietFrames = KEEP_FRAMES;
    }

    // ================================================================ the writer's side

    /** Counts steps just run; publishes when a frame of simulated time has passed and someone reads. */
    public void afterSteps(int n) {
        stepsSince += n;
        if (frameDeferred) {
            return;
        }
        if (dirty) {
            if (reads != 0) {
                publish(); // a reader came and found the topology change unpublished
            }
            return;
        }
        if (stepsSince * c.time.displayRate() >= c.time.simRate()) {
            frameEnded();
        }
    }

    /** Start of a {@link PhysicalModel#draw_physics()} frame in locked mode: publish once, at its end. */
    public void beginFrame() {
        frameDeferred = true;
    }

    /** End of a locked-mode frame: publishes if someone reads (see {@link #beginFrame()}). */
    public void endFrame() {
        frameDeferred = false;
        if (dirty) {
            if (reads != 0) {
                publish();
            }
        } else if (stepsSince > 0) {
            frameEnded();
        }
    }

    /** Clears a frame's deferral without publishing (the frame ended by an exception). */
    public void abandonFrame() {
        frameDeferred = false;
    }

    private void frameEnded() {
        long r = reads;
        if (r != seenReads) {
            seenReads = r;
            quietFrames = 0;
            publish();
        } else if (quietFrames < KEEP_FRAMES) {
            quietFrames++;
            publish();
        }
        // else nobody reads: no copy; the step after the next read publishes (stepsSince has kept counting)
    }

    /**
     * A topology change has been compiled and installed (or the model initialised): published at once when a reader
     * has ever read or the model is stepped in realtime (where the reader cannot publish); else marked dirty.
     */
    public void topologyChanged() {
        version++;
        if (reads != 0 || c.own != null) {
            publish();
        } else {
            dirty = true;
        }
    }

    /**
     * The directory changed but the new plan is installed later ({@link InstallCommand}, which then calls
     * {@link #topologyChanged()}): a publication in between reads the new directory, not the cached one.
     */
    public void topologyEdited() {
        version++;
    }

    /** Before realtime stepping begins (under the lock, in locked mode): publishes a pending topology change. */
    public void publishIfDirty() {
        if (dirty && c.initialized) {
            publish();
        }
    }

    /** Copies the current state into the back buffer and hands it to the reader. */
    public void publish() {
        stepsSince = 0;
        dirty = false;
        publishes++;
        SnapshotBuffer s = exchange.back();
        Directory dir = c.dir;
        int nm = dir.mats.size();
        boolean withLinks = exchange.links;
        int nl = withLinks ? dir.links.size() : 0;
        s.ensure(nm, nl);
        if (massCacheVersion != version || massCount != nm) {
            cacheMasses(dir, nm);
        }
        if (s.massVersion != massStamp) {
            System.arraycopy(massTypes, 0, s.massTypes, 0, nm);
            s.massVersion = massStamp;
        }
        copyMasses(s, nm);
        if (withLinks) {
            if (linkCacheVersion != version || linkCount != nl) {
                cacheLinks(dir, nl);
            }
            if (s.linkVersion != linkStamp) {
                System.arraycopy(ends, 0, s.ends, 0, 2 * nl);
                System.arraycopy(shapes, 0, s.shapes, 0, nl);
                System.arraycopy(linkTypes, 0, s.linkTypes, 0, nl);
                s.linkVersion = linkStamp;
            }
            long edits = engine.linkParameterEdits();
            if (s.lengthsCopied != linkStamp || s.lengthEdits != edits) {
                // lengths and plane positions: only when they were set since this buffer last copied them
                double[] len = s.length;
                int[] ids = linkIds;
                for (int l = 0; l < nl; l++) {
                    len[l] = engine.linkLength(ids[l]);
                }
                for (int k = 0; k < planeCount; k++) {
                    int l = planeLinks[k];
                    s.plane[l] = engine.planePosition(ids[l]);
                }
                s.lengthsCopied = linkStamp;
                s.lengthEdits = edits;
                linksCopied += nl;
            }
            lastEdits = edits;
        }
        long step = engine.stepCount();
        s.masses = nm;
        s.links = nl;
        s.hasLinks = withLinks;
        s.motion = exchange.motion;
        lastMotion = s.motion;
        lastLinks = withLinks;
        s.step = step;
        lastStep = step;
        exchange.publish();
    }

    private void copyMasses(SnapshotBuffer s, int nm) {
        if (lastId.length < nm) {
            lastId = java.util.Arrays.copyOf(lastId, s.massTypes.length);
            lastSum = java.util.Arrays.copyOf(lastSum, 3 * s.massTypes.length);
        }
        long step = engine.stepCount();
        long since = lastStep < 0 ? 0 : step - lastStep;
        UnitScale u = c.units();
        engine.copyPositions(massIds, nm, s.pos);
        if (exchange.motion) {
            for (int i = 0; i < nm; i++) {
                copyMotion(s, i, since, u);
            }
            s.zeroStamp = -1;
        } else {
            // velocities and forces only on request (they cost about as much again as the positions): zero, once
            // per buffer and topology, except the haptic avatars' forces, copied every time
            if (s.zeroStamp != massStamp) {
                java.util.Arrays.fill(s.vel, 0, 3 * nm, 0.0);
                java.util.Arrays.fill(s.force, 0, 3 * nm, 0.0);
                s.zeroStamp = massStamp;
            }
            for (int k = 0; k < avatarCount; k++) {
                copyMotion(s, avatars[k], since, u);
            }
        }
        massesCopied += nm;
    }

    /** Copies the velocity and force of mass index {@code i}. */
    private void copyMotion(SnapshotBuffer s, int i, long since, UnitScale u) {
        int id = massIds[i];
        int q = 3 * i;
        MassKind kind = massKinds[i];
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
            long before;
            if (taken == 0 && (before = engine.lastTakenForce(id, tmp)) > 0) {
                // taken at this very step (a reader publishing between a haptic loop's step and its take):
                // the buffer is empty, the sum just taken holds this step's force
                per = 1.0 / before;
            } else if (since > 0 && taken > since && lastId[i] == id) {
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

    /** Once per topology version: each mass's id, kind and type. */
    private void cacheMasses(Directory dir, int nm) {
        if (massIds.length < nm) {
            int cap = Math.max(nm, massIds.length * 3 / 2 + 8);
            massIds = new int[cap];
            massKinds = new MassKind[cap];
            massTypes = new matModuleType[cap];
            avatars = new int[cap];
        }
        avatarCount = 0;
        for (int i = 0; i < nm; i++) {
            int id = dir.mats.idAt(i);
            massIds[i] = id;
            MassKind kind = engine.massKind(id);
            massKinds[i] = kind;
            massTypes[i] = ModuleTypes.of(kind);
            if (kind == MassKind.HAPTIC_INPUT3D) {
                avatars[avatarCount++] = i;
            }
        }
        massCount = nm;
        massStamp++;
        massCacheVersion = version;
    }

    /** Once per topology version (when links are read): each interaction's id, end indices, type and shape. */
    private void cacheLinks(Directory dir, int nl) {
        if (linkIds.length < nl) {
            int cap = Math.max(nl, linkIds.length * 3 / 2 + 8);
            linkIds = new int[cap];
            ends = new int[2 * cap];
            shapes = new int[cap];
            linkTypes = new linkModuleType[cap];
            planeLinks = new int[cap];
        }
        planeCount = 0;
        for (int l = 0; l < nl; l++) {
            int id = dir.links.idAt(l);
            linkIds[l] = id;
            ends[2 * l] = dir.mats.indexOf(engine.linkMassA(id));
            ends[2 * l + 1] = dir.mats.indexOf(engine.linkMassB(id));
            LinkKind kind = engine.linkKind(id);
            linkTypes[l] = ModuleTypes.of(kind);
            if (kind == LinkKind.PLANE_CONTACT3D) {
                shapes[l] = SHAPE_PLANE + engine.linkAxis(id);
                planeLinks[planeCount++] = l;
            } else {
                shapes[l] = kind.isOneDimensional() ? SHAPE_1D : SHAPE_3D;
            }
        }
        linkCount = nl;
        linkStamp++;
        linkCacheVersion = version;
        linkWalks++;
    }

    /** @return the number of calls of {@link #request()} so far (for tests). */
    public long reads() {
        return reads;
    }
}
