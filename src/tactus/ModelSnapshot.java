package tactus;

import tactus.internal.snapshot.SnapshotBuffer;
import tactus.internal.snapshot.SnapshotWriter;


/**
 * A consistent copy of a model's state at one step, for drawing: every mass's position, type and name index
 * (and, on request, velocity and force: {@link #requestMotion}), and, unless the reader declined them
 * ({@link #requestLinks}), every interaction's two mass indices, type and elongation, all taken at the same step.
 * Read it with {@link PhysicalModel#getSnapshot()} from the drawing thread: it never blocks the thread that steps
 * the model (audio or haptics) and is never torn.
 *
 * <p>A snapshot object belongs to the reading thread until its next call to {@code getSnapshot()}; it is then
 * recycled. Copy what you need to keep. Indices are insertion-order indices as in
 * {@link PhysicalModel#getMatPosAt(int)}.
 */
public final class ModelSnapshot {
    private final SnapshotBuffer buf;

    ModelSnapshot(SnapshotBuffer buf) {
        this.buf = buf;
    }

    /**
     * Asks the model to copy every mass's velocity and force into its snapshots from the next publication on
     * (false: only the haptic avatars' forces, the default, which keeps publishing cheap for the thread that
     * steps the model). The renderer asks for them while it colours by speed or force. Any thread.
     *
     * @param on true to include velocities and forces of every mass
     */
    public void requestMotion(boolean on) {
        buf.exchange.motion = on;
    }

    /**
     * Asks the model to copy its interactions (ends, types, elongations) into its snapshots from the next
     * publication on (the default), or not (false: masses only, which spares the thread that steps the model a walk
     * over every interaction each display frame). The renderer asks for them while it draws links. Any thread.
     *
     * @param on true to include the interactions
     */
    public void requestLinks(boolean on) {
        buf.exchange.links = on;
    }

    /**
     * {@return true if this copy carries the interactions; false if the reader asked for masses only
     *     ({@link #requestLinks}), and {@link #getNumberOfLinks()} is then 0}
     */
    public boolean hasLinks() {
        return buf.hasLinks;
    }

    /**
     * {@return true if this copy carries the velocity and force of every mass; false if only the haptic avatars'
     *         forces (the other masses then read 0)}
     */
    public boolean hasMotion() {
        return buf.motion;
    }

    /** {@return the step count at which the copy was taken, or -1 before the first publication} */
    public long getStep() {
        return buf.step;
    }

    /** {@return the number of masses in the copy} */
    public int getNumberOfMats() {
        return buf.masses;
    }

    /** {@return the number of interactions in the copy (0 when it carries none: {@link #hasLinks()})} */
    public int getNumberOfLinks() {
        return buf.links;
    }

    /** {@return the x coordinate of mass {@code i}, in model length units} */
    public double x(int i) {
        return buf.pos[3 * checkMass(i)];
    }

    /** {@return the y coordinate of mass {@code i}} */
    public double y(int i) {
        return buf.pos[3 * checkMass(i) + 1];
    }

    /** {@return the z coordinate of mass {@code i}} */
    public double z(int i) {
        return buf.pos[3 * checkMass(i) + 2];
    }

    /** {@return the x component of the velocity of mass {@code i}, in length units per second} */
    public double vx(int i) {
        return buf.vel[3 * checkMass(i)];
    }

    /** {@return the y component of the velocity of mass {@code i}, in length units per second} */
    public double vy(int i) {
        return buf.vel[3 * checkMass(i) + 1];
    }

    /** {@return the z component of the velocity of mass {@code i}, in length units per second} */
    public double vz(int i) {
        return buf.vel[3 * checkMass(i) + 2];
    }

    /** {@return the speed of mass {@code i} (the norm of its velocity over the last step), length units per second} */
    public double speed(int i) {
        int q = 3 * checkMass(i);
        return Math.sqrt(buf.vel[q] * buf.vel[q] + buf.vel[q + 1] * buf.vel[q + 1] + buf.vel[q + 2] * buf.vel[q + 2]);
    }

    /**
     * {@return the x component of the force of the interactions on mass {@code i} at this step, in the model's
     *         force unit (newtons in REAL_UNITS); for a haptic avatar, the mean per step since its force was last
     *         taken (what the device is being sent), for fixed and driven masses 0}
     */
    public double fx(int i) {
        return buf.force[3 * checkMass(i)];
    }

    /** {@return the y component of the force on mass {@code i} (see {@link #fx(int)})} */
    public double fy(int i) {
        return buf.force[3 * checkMass(i) + 1];
    }

    /** {@return the z component of the force on mass {@code i} (see {@link #fx(int)})} */
    public double fz(int i) {
        return buf.force[3 * checkMass(i) + 2];
    }

    /** {@return the norm of the force on mass {@code i} (see {@link #fx(int)})} */
    public double forceNorm(int i) {
        int q = 3 * checkMass(i);
        return Math.sqrt(buf.force[q] * buf.force[q] + buf.force[q + 1] * buf.force[q + 1] + buf.force[q + 2] * buf.force[q + 2]);
    }

    /** Writes the position of mass {@code i} into {@code out} and returns it. */
    public Vect3D getMatPos(int i, Vect3D out) {
        int q = 3 * checkMass(i);
        return out.set(buf.pos[q], buf.pos[q + 1], buf.pos[q + 2]);
    }

    /** {@return the type of mass {@code i}} */
    public matModuleType getMatType(int i) {
        return buf.massTypes[checkMass(i)];
    }

    /** {@return the index of the first mass of interaction {@code l}} */
    public int getLinkMat1Idx(int l) {
        return buf.ends[2 * checkLink(l)];
    }

    /** {@return the index of the second mass of interaction {@code l} (the first again for a plane contact)} */
    public int getLinkMat2Idx(int l) {
        return buf.ends[2 * checkLink(l) + 1];
    }

    /**
     * {@return the elongation of interaction {@code l}: its distance minus its length parameter, in model length
     *     units (for a plane contact its gap to the plane minus its offset; for a 1D spring its z distance), as
     *     the model's own {@code getLinkElongationAt} gives at the copy's step. Computed from the copied positions
     *     on the reading thread}
     */
    public double getLinkElongation(int l) {
        int k = checkLink(l);
        int a = 3 * buf.ends[2 * k];
        int shape = buf.shapes[k];
        double d;
        if (shape >= SnapshotWriter.SHAPE_PLANE) {
            d = buf.pos[a + shape - SnapshotWriter.SHAPE_PLANE] - buf.plane[k];
        } else {
            int b = 3 * buf.ends[2 * k + 1];
            if (shape == SnapshotWriter.SHAPE_1D) {
                d = buf.pos[a + 2] - buf.pos[b + 2];
            } else {
                double dx = buf.pos[a] - buf.pos[b];
                double dy = buf.pos[a + 1] - buf.pos[b + 1];
                double dz = buf.pos[a + 2] - buf.pos[b + 2];
                d = Math.sqrt(dx * dx + dy * dy + dz * dz);
            }
        }
        return d - buf.length[k];
    }

    /** {@return the type of interaction {@code l}} */
    public linkModuleType getLinkType(int l) {
        return buf.linkTypes[checkLink(l)];
    }

    private int checkMass(int i) {
        if (i < 0 || i >= buf.masses) {
            throw new IndexOutOfBoundsException("snapshot mass index " + i + " out of range 0.." + (buf.masses - 1));
        }
        return i;
    }

    private int checkLink(int l) {
        if (!buf.hasLinks && buf.step >= 0) {
            throw new IllegalStateException("snapshot link " + l + ": this copy carries no interactions (the "
                    + "reader asked for masses only with requestLinks(false); call requestLinks(true))");
        }
        if (l < 0 || l >= buf.links) {
            throw new IndexOutOfBoundsException("snapshot link index " + l + " out of range 0.." + (buf.links - 1));
        }
        return l;
    }

    /** Makes room for a model of this size; allocates only when the model grew. */
}
