package tactus;

/** Inverse-square attraction between two masses, f = -A / d^2, while d exceeds a limit distance. */
public final class Attractor3D extends Interaction {
    Attractor3D(PhysicalModel model, int id) {
        super(model, id);
    }

    /** @return the attraction factor A (REAL_UNITS: N·m^2); negative values repel. */
    public double getAttraction() {
        model.enter(this);
        try {
            return model.core.params.attraction("getAttraction", id);
        } finally {
            model.exit();
        }
    }

    /** Sets the attraction factor A (REAL_UNITS: N·m^2). */
    public void setAttraction(double a) {
        model.enter(this);
        try {
            model.core.params.setAttraction("setAttraction", id, a);
        } finally {
            model.exit();
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
