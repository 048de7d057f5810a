package tactus;

import tactus.internal.calls.ModuleCalls.LinkParam;


/** Inverse-square attraction between two masses, f = -A / d^2, while d exceeds a limit distance. */
public final class Attractor3D extends Interaction {
    Attractor3D(ModuleHandles handles, int id) {
        super(handles, id);
    }

    /** {@return the attraction factor A (REAL_UNITS: N·m^2); negative values repel} */
    public double getAttraction() {
        return param(LinkParam.ATTRACTION);
    }

    /** Sets the attraction factor A (REAL_UNITS: N·m^2). */
    public void setAttraction(double a) {
        checkValid();
        calls.setLinkParam(id, "setAttraction", LinkParam.ATTRACTION, a);
    }

    /** {@return the limit distance below which no force acts} */
    public double getLimit() {
        return length();
    }

    /** Sets the limit distance, &gt; 0. */
    public void setLimit(double d) {
        length("setLimit", d);
    }
}
