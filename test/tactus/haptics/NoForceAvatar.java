package tactus.haptics;

/** An avatar link for tests that need a loop but no model: it ignores the target and puts no force on the hand. */
public class NoForceAvatar implements AvatarLink {
    @Override
    public void setTarget(double x, double y, double z) {
        // nothing
    }

    @Override
    public void takeForce(double[] out) {
        out[0] = 0;
        out[1] = 0;
        out[2] = 0;
    }

    @Override
    public void step(int n) {
        // nothing
    }
}
