package tactus;

/** A fixed point in 3D: interactions act on it but it never moves. */
public final class Ground3D extends Mass {
    Ground3D(PhysicalModel model, int id) {
        super(model, id);
    }
}
