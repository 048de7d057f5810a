package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** Inverse-square attraction between two masses, f = -A / d^2, while d exceeds a limit distance. */
public final class Attractor3D extends Interaction {
    Attractor3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }

    /** @return the attraction factor A (REAL_UNITS: N·m^2); negative values repel. */
    public double getAttraction() {
        enter();
        try {
            return core.params.attraction("getAttraction", id);
        } finally {
            exit();
        }
    }

    /** Sets the attraction factor A (REAL_UNITS: N·m^2). */
    public void setAttraction(double a) {
        enter();
        try {
            core.params.setAttraction("setAttraction", id, a);
        } finally {
            exit();
        }
    }

    /** @return the limit distance below which no force acts. */
    public double getLimit() {
        return length();
    }

    /** Sets the limit distance, &gt; 0. */
    public void setLimit(double d) {
        length("setLimit", d);
    }
}
