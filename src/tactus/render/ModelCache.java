package tactus.render;

import java.util.concurrent.locks.Lock;

import tactus.ModelSnapshot;
import tactus.PhysicalModel;
import tactus.linkModuleType;
import tactus.matModuleType;

/**
 * What the renderer needs beside the snapshot: each mass's inertia (for the radius), each interaction's length
 * parameter (for the strain) and each plane contact's axis and plane position. These are read from the model under
 * its lock, but only when the topology seen in the snapshot changes (a mass or interaction count, type or end
 * differs from last frame's), when another model is drawn, or on {@link #invalidate()}; otherwise the per-frame
 * check is a comparison of plain arrays, without locking or allocating.
 */
final class ModelCache {
    private PhysicalModel model;
    private boolean dirty = true;
    private int masses = -1;
    private int links = -1;
    private boolean hasLinks;
    private matModuleType[] massTypes = new matModuleType[0];
    private linkModuleType[] linkTypes = new linkModuleType[0];
    private int[] ends = new int[0];
    private double[] inertia = new double[0];
    private double[] restLength = new double[0];
    private int[] planeAxis = new int[0];
    private double[] planePosition = new double[0];
    private int refreshes;

    /** Drops the model (so that it can be collected) and forces a re-read at the next {@link #sync}. */
    void forget() {
        model = null;
        dirty = true;
    }

    /** Forces a re-read of masses and lengths at the next {@link #sync}. */
    void invalidate() {
        dirty = true;
    }

    /** @return how many times the cache was read from the model (for tests). */
    int refreshes() {
        return refreshes;
    }

    /**
     * Returns the newest snapshot of the model, with this cache matching its topology.
     *
     * @param m the model
     * @return the snapshot to draw
     */
    ModelSnapshot sync(PhysicalModel m) {
        ModelSnapshot s = m.getSnapshot();
        if (!dirty && m == model && sameTopology(s)) {
            return s;
        }
        Lock lock = m.getLock();
        lock.lock();
        try {
            // Under the lock (locked mode) the newest snapshot matches the live topology: an edit publishes it, or
            // this call does. In realtime mode the owner publishes every edit before the editor's call returns.
            // (Before init() the snapshot is empty; nothing is read then.)
            s = m.getSnapshot();
            boolean live = s.getNumberOfMats() == m.getNumberOfMats()
                    && (!s.hasLinks() || s.getNumberOfLinks() == m.getNumberOfLinks());
            read(m, s, live);
            model = m;
            dirty = !live;
        } finally {
            lock.unlock();
        }
        return s;
    }

    private boolean sameTopology(ModelSnapshot s) {
        int nm = s.getNumberOfMats();
        int nl = s.getNumberOfLinks();
        if (nm != masses || nl != links || s.hasLinks() != hasLinks) {
            return false;
        }
        for (int i = 0; i < nm; i++) {
            if (s.getMatType(i) != massTypes[i]) {
                return false;
            }
        }
        for (int l = 0; l < nl; l++) {
            if (s.getLinkType(l) != linkTypes[l] || s.getLinkMat1Idx(l) != ends[2 * l]
                    || s.getLinkMat2Idx(l) != ends[2 * l + 1]) {
                return false;
            }
        }
        return true;
    }

    private void read(PhysicalModel m, ModelSnapshot s, boolean live) {
        refreshes++;
        int nm = s.getNumberOfMats();
        int nl = s.getNumberOfLinks();
        if (massTypes.length < nm) {
            massTypes = new matModuleType[nm];
            inertia = new double[nm];
        }
        if (linkTypes.length < nl) {
            linkTypes = new linkModuleType[nl];
            ends = new int[2 * nl];
            restLength = new double[nl];
            planeAxis = new int[nl];
            planePosition = new double[nl];
        }
        for (int i = 0; i < nm; i++) {
            matModuleType t = s.getMatType(i);
            massTypes[i] = t;
            inertia[i] = live && isSimulated(t) ? m.getMatMassAt(i) : 0;
        }
        for (int l = 0; l < nl; l++) {
            linkModuleType t = s.getLinkType(l);
            linkTypes[l] = t;
            ends[2 * l] = s.getLinkMat1Idx(l);
            ends[2 * l + 1] = s.getLinkMat2Idx(l);
            restLength[l] = live ? m.getLinkDRestAt(l) : 0;
            if (live && t == linkModuleType.PlaneContact3D) {
                planeAxis[l] = m.getPlaneOrientationAt(l);
                planePosition[l] = m.getPlanePositionAt(l);
            } else {
                planeAxis[l] = -1;
                planePosition[l] = 0;
            }
        }
        masses = nm;
        links = nl;
        hasLinks = s.hasLinks();
    }

    /**
     * True for masses that the model moves by their inertia: not fixed points, avatars or position drivers
     * (the drawer colours only these by speed or force; the others have no inertia to cache).
     */
    static boolean isSimulated(matModuleType t) {
        switch (t) {
            case Ground3D:
            case Ground1D:
            case HapticInput3D:
            case PosInput3D:
            case UNDEFINED:
                return false;
            default:
                return true;
        }
    }

    /** @return the inertia of mass {@code i} (0 for fixed and driven masses). */
    double inertia(int i) {
        return inertia[i];
    }

    /** @return the length parameter of interaction {@code l}. */
    double restLength(int l) {
        return restLength[l];
    }

    /** @return the axis (0, 1, 2) of plane contact {@code l}, or -1 when it is not a plane contact. */
    int planeAxis(int l) {
        return planeAxis[l];
    }

    /** @return the plane coordinate on its axis of plane contact {@code l}. */
    double planePosition(int l) {
        return planePosition[l];
    }
}
