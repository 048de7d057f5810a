package tactus.hapticstability;

import tactus.haptics.AvatarLink;

/**
 * For measurements: an {@link AvatarLink} that passes every call to another one; a subclass overrides what it watches
 * or changes (the target, the force).
 */
public abstract class ForwardingAvatarLink implements AvatarLink {
    /** The link every call goes to. */
    protected final AvatarLink inner;

    /** A link that forwards to inner. */
    protected ForwardingAvatarLink(AvatarLink inner) {
        this.inner = inner;
    }

    @Override
    public void setTarget(double x, double y, double z) {
        inner.setTarget(x, y, z);
    }

    @Override
    public void takeForce(double[] out) {
        takeForceCounted(out);
    }

    @Override
    public long takeForceCounted(double[] out) {
        return inner.takeForceCounted(out);
    }

    @Override
    public boolean neverWaits() {
        return inner.neverWaits();
    }

    @Override
    public void step(int n) {
        inner.step(n);
    }

    @Override
    public void beginStepping() {
        inner.beginStepping();
    }

    @Override
    public void endStepping() {
        inner.endStepping();
    }
}
