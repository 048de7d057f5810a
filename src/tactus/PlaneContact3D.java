package tactus;

import tactus.internal.calls.ModuleCalls.LinkParam;


/**
 * A one-sided contact between a mass and an axis-aligned plane: while the mass coordinate q on
 * the plane's axis is below {@code position + l0}, it is pushed back with
 * {@code -K t - Z (q(n) - q(n-1))}, where {@code t = q - position - l0}.
 */
public final class PlaneContact3D extends ElasticInteraction {
    PlaneContact3D(ModuleHandles handles, int id) {
        super(handles, id);
    }

    /** {@return the plane's coordinate on its axis} */
    public double getPlanePosition() {
        return param(LinkParam.PLANE_POSITION);
    }

    /** Moves the plane along its axis. */
    public void setPlanePosition(double pos) {
        checkValid();
        calls.setLinkParam(id, "setPlanePosition", LinkParam.PLANE_POSITION, pos);
    }

    /** {@return the plane's axis: 0 (x), 1 (y) or 2 (z)} */
    public int getOrientation() {
        return (int) param(LinkParam.PLANE_AXIS);
    }
}
