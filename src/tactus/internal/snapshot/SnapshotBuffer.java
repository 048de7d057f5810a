package tactus.internal.snapshot;

import tactus.ModelSnapshot;
import tactus.internal.model.ApiAccess;
import tactus.linkModuleType;
import tactus.matModuleType;

/**
 * One buffer of the snapshot exchange: the arrays a {@link SnapshotWriter} fills and the public
 * {@code tactus.ModelSnapshot} reads (its {@link #view}). Not API.
 */
public final class SnapshotBuffer {
    public long step = -1;
    public int masses;
    public int links;
    public double[] pos = new double[0];
    public double[] vel = new double[0];
    public double[] force = new double[0];
    public matModuleType[] massTypes = new matModuleType[0];
    public int[] ends = new int[0];
    /** Per interaction: how its distance is measured ({@link SnapshotWriter#SHAPE_3D} and so on). */
    public int[] shapes = new int[0];
    /** Per interaction: its length parameter, and for a plane contact its plane coordinate. */
    public double[] length = new double[0];
    public double[] plane = new double[0];
    public linkModuleType[] linkTypes = new linkModuleType[0];
    /** The topology version whose mass types, and interaction ends, types and shapes, this buffer holds. */
    public int massVersion = -1;
    public int linkVersion = -1;
    /** The mass cache stamp for which the velocities and forces of every mass but the avatars are zero. */
    public int zeroStamp = -1;
    /** The link cache stamp and the engine's count of link parameter edits when the lengths were copied. */
    public int lengthsCopied = -1;
    public long lengthEdits = -1;
    public boolean hasLinks;

    /** The exchange this buffer belongs to (where the reader's requests are kept). */
    public final SnapshotExchange exchange;
    /** True when this copy carries every mass's velocity and force. */
    public boolean motion;
    /** The public view of this buffer, made once. */
    public final ModelSnapshot view;

    SnapshotBuffer(SnapshotExchange exchange) {
        this.exchange = exchange;
        this.view = ApiAccess.get().newSnapshotView(this);
    }

    /** Grows the arrays to hold this many masses and interactions. */
    public void ensure(int nMass, int nLink) {
        if (massTypes.length < nMass) {
            int cap = Math.max(nMass, massTypes.length * 3 / 2 + 8);
            pos = new double[3 * cap];
            vel = new double[3 * cap];
            force = new double[3 * cap];
            massTypes = new matModuleType[cap];
            massVersion = -1;
            zeroStamp = -1;
        }
        if (linkTypes.length < nLink) {
            int cap = Math.max(nLink, linkTypes.length * 3 / 2 + 8);
            ends = new int[2 * cap];
            shapes = new int[cap];
            length = new double[cap];
            plane = new double[cap];
            linkTypes = new linkModuleType[cap];
            linkVersion = -1;
            lengthsCopied = -1;
        }
    }
}
