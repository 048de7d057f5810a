package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/**
 * A one-sided contact between a mass and an axis-aligned plane: while the mass coordinate q on
 * the plane's axis is below {@code position + l0}, it is pushed back with
 * {@code -K t - Z (q(n) - q(n-1))}, where {@code t = q - position - l0}.
 */
public final class PlaneContact3D extends ElasticInteraction {
    PlaneContact3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }

    /** @return the plane's coordinate on its axis. */
    public double getPlanePosition() {
        enter();
        try {
            return core.params.planePosition("getPlanePosition", id);
        } finally {
            exit();
        }
    }

    /** Moves the plane along its axis. */
    public void setPlanePosition(double pos) {
        enter();
        try {
            core.params.setPlanePosition("setPlanePosition", id, pos);
        } finally {
            exit();
        }
    }

    /** @return the plane's axis: 0 (x), 1 (y) or 2 (z). */
    public int getOrientation() {
        enter();
        try {
            return core.params.planeAxis("getOrientation", id);
        } finally {
            exit();
        }
    }
}
