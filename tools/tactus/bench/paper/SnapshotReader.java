package tactus.bench.paper;

import tactus.ModelSnapshot;
import tactus.PhysicalModel;

/**
 * Tactus only: what a sketch's {@code draw()} reads each frame, read the Tactus way: {@link PhysicalModel#getSnapshot()}
 * (no lock; the stepping thread never waits), then every mass position and every link's ends and elongation
 * from the snapshot. {@link PaperScenes} loads this class by name and calls it from its reader thread.
 */
public final class SnapshotReader implements Runnable {
    private final PhysicalModel mdl;
    /** Sum of what was read (keeps the reads alive). */
    public double sink;

    /** @param model the {@link PhysicalModel} to read */
    public SnapshotReader(Object model) {
        this.mdl = (PhysicalModel) model;
    }

    @Override
    public void run() {
        ModelSnapshot s = mdl.getSnapshot();
        int mats = s.getNumberOfMats();
        for (int i = 0; i < mats; i++) {
            sink += s.x(i) + s.y(i) + s.z(i);
        }
        int links = s.getNumberOfLinks();
        for (int l = 0; l < links; l++) {
            sink += s.getLinkMat1Idx(l) + s.getLinkMat2Idx(l) + s.getLinkElongation(l);
        }
    }
}
