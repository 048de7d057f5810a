package tactus;

/** A fixed point for 1D models. */
public final class Ground1D extends Mass {
    Ground1D(PhysicalModel model, int id) {
        super(model, id);
    }
}
