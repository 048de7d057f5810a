package tactus.audio;

/** A {@link SteppedModel} that passes every call to another and counts the stepping calls (for the block tests). */
final class CountingSteppedModel implements SteppedModel {
    private final SteppedModel m;
    /** True: {@link #stepRecording} is the interface's default (step and read one at a time), not the model's own. */
    private final boolean interfaceDefault;
    int steps;
    int recordings;
    int recordedSteps;
    /** Calls of {@link #beginSample()}; and how many of them were not yet ended. */
    int samplesBegun;
    int samplesOpen;

    CountingSteppedModel(SteppedModel m) {
        this(m, false);
    }

    CountingSteppedModel(SteppedModel m, boolean interfaceDefault) {
        this.m = m;
        this.interfaceDefault = interfaceDefault;
    }

    @Override public int stepRate() { return m.stepRate(); }
    @Override public void setStepRate(int r) { m.setStepRate(r); }
    @Override public void step() { steps++; m.step(); }
    @Override public boolean isHalted() { return m.isHalted(); }
    @Override public java.util.concurrent.locks.Lock sampleLock() { return m.sampleLock(); }
    @Override public void beginSample() { samplesBegun++; samplesOpen++; m.beginSample(); }
    @Override public void endSample() { samplesOpen--; m.endSample(); }
    @Override public int resolveMass(String name) { return m.resolveMass(name); }
    @Override public int resolveLink(String name, boolean withForce) { return m.resolveLink(name, withForce); }
    @Override public int resolveAvatar(String name) { return m.resolveAvatar(name); }
    @Override public double massPosition(int mass, int axis) { return m.massPosition(mass, axis); }
    @Override public double massPositionForSetup(int mass, int axis) { return m.massPositionForSetup(mass, axis); }
    @Override public double linkElongation(int link) { return m.linkElongation(link); }
    @Override public double linkTension(int link) { return m.linkTension(link); }
    @Override public void setAvatarTarget(int a, double x, double y, double z) { m.setAvatarTarget(a, x, y, z); }
    @Override public void takeAvatarForce(int a, double[] out) { m.takeAvatarForce(a, out); }
    @Override public boolean reattachMass(int mass) { return m.reattachMass(mass); }
    @Override public boolean reattachLink(int link) { return m.reattachLink(link); }
    @Override public boolean reattachAvatar(int a) { return m.reattachAvatar(a); }

    @Override
    public int stepRecording(int n, int[] masses, int[] axes, int count, double[] out) {
        recordings++;
        if (samplesOpen != 1) {
            throw new AssertionError("a block is recorded between beginSample() and endSample(): " + samplesOpen + " open");
        }
        int ran = interfaceDefault ? SteppedModel.super.stepRecording(n, masses, axes, count, out)
                : m.stepRecording(n, masses, axes, count, out);
        recordedSteps += ran;
        return ran;
    }
}
