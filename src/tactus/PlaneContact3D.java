package tactus;

/**
 * A one-sided contact between a mass and an axis-aligned plane: while the mass coordinate q on
 * the plane's axis is below {@code position + l0}, it is pushed back with
 * {@code -K t - Z (q(n) - q(n-1))}, where {@code t = q - position - l0}.
 */
public final class PlaneContact3D extends ElasticInteraction {
    PlaneContact3D(PhysicalModel model, int id) {
        super(model, id);
    }

    /** @return the plane's coordinate on its axis. */
    public double getPlanePosition() {
        model.enter(this);
        try {
            return model.core.params.planePosition("getPlanePosition", id);
        } finally {
            model.exit();
        }
    }

    /** Moves the plane along its axis. */
    public void setPlanePosition(double pos) {
        model.enter(this);
        try {
            model.core.params.setPlanePosition("setPlanePosition", id, pos);
        } finally {
            model.exit();
        }
    }

    /** @return the plane's axis: 0 (x), 1 (y) or 2 (z). */
    public int getOrientation() {
        model.enter(this);
        try {
            return model.core.params.planeAxis("getOrientation", id);
        } finally {
            model.exit();
        }
    }
}
