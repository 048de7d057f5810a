package tactus;

/** Inverse-square attraction between two masses, f = -A / d^2, while d exceeds a limit distance. */
public final class Attractor3D extends Interaction {
    Attractor3D(PhysicalModel model, int id) {
        super(model, id);
    }

    /** @return the attraction factor A (REAL_UNITS: N·m^2); negative values repel. */
    public double getAttraction() {
        checkValid();
        return model.linkAuxOut(id);
    }

    /** Sets the attraction factor A (REAL_UNITS: N·m^2). */
    public void setAttraction(double a) {
        checkValid();
        model.setLinkAuxOf("setAttraction", id, a);
    }

    /** @return the limit distance below which no force acts. */
    public double getLimit() {
        return length();
    }

    /** Sets the limit distance, finite and &gt; 0 (an {@link IllegalArgumentException} otherwise). */
    public void setLimit(double d) {
        length(d);
    }
}
