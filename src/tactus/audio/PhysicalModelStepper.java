package tactus.audio;

import java.util.Arrays;
import java.util.concurrent.locks.LockSupport;
import java.util.function.IntConsumer;
import tactus.Mass;
import tactus.PhysicalModel;
import tactus.linkModuleType;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * The one adapter from {@link SteppedModel} to the public {@link PhysicalModel} API. Creating it puts the model in
 * realtime stepping ({@link PhysicalModel#beginRealtimeStepping()}): the thread that steps it (Minim's audio thread)
 * takes no lock and never waits for another thread; other threads' changes are queued and applied between two
 * samples. It also holds the model's rate ({@link PhysicalModel#holdSimRate(Object)}): from then on only
 * {@link #setStepRate(int)} changes it, and {@code setSimRate} from the sketch is refused. If the mode ends while the
 * model is still played ({@code endRealtimeStepping()}), the next step asks the {@link AudioHelper} thread to begin
 * it again (see {@link #step()}); to take the model back, stop playing it first.
 *
 * <p>Names are resolved once into handles (slots that keep the name, so that an element removed and added again
 * is found again by {@link #reattachMass(int)} and its kin). The per-sample methods run on the audio thread only,
 * use scratch vectors of their own and allocate nothing ({@code PhyUGenAllocationTest}); the setup methods, called
 * by the sketch's thread, share no scratch state with them. Interaction reads look the name up in a hash table per
 * call.
 */
public final class PhysicalModelStepper implements SteppedModel {
    private final PhysicalModel model;
    private final boolean realUnits;
    private final Object rateHolder;
    /** Sets the model's rate while this stepper holds it; replaced when realtime stepping is begun again. */
    private volatile IntConsumer rateSetter;
    /** True from when the audio thread finds the realtime mode ended until the helper has begun it again. */
    private volatile boolean resuming;
    private volatile long resumes;
    /** Scratch vectors of the audio thread (the per-sample methods); never touched by a setup method. */
    private final Vect3D audioScratch = new Vect3D();
    private final Vect3D audioTarget = new Vect3D();
    private MassSlot[] masses = new MassSlot[4];
    private int massCount;
    private LinkSlot[] links = new LinkSlot[4];
    private int linkCount;
    private String[] avatars = new String[2];
    private int avatarCount;
    private volatile int rate;
    /** The handles {@link #stepRecording} passes to the model; the audio thread's own. */
    private Mass[] recordMasses = new Mass[0];
    /** True while the audio thread's sample holds the model ({@link #beginSample()}); the audio thread's own. */
    private boolean inSample;

    private static final int RULE_UNSUPPORTED = -1;
    private static final int RULE_ALWAYS = 0;
    private static final int RULE_COMPRESSED = 1;
    private static final int RULE_STRETCHED = 2;

    /** A resolved mass: its name and its current handle (replaced when the mass is added again). */
    private static final class MassSlot {
        final String name;
        volatile Mass mass;

        MassSlot(String name, Mass mass) {
            this.name = name;
            this.mass = mass;
        }
    }

    /** A resolved interaction: its name, how its force is read, and the audio thread's last elongation. */
    private static final class LinkSlot {
        final String name;
        final boolean withForce;
        int rule;
        double lastElongation;

        LinkSlot(String name, boolean withForce, int rule, double lastElongation) {
            this.name = name;
            this.withForce = withForce;
            this.rule = rule;
            this.lastElongation = lastElongation;
        }
    }

    /** Wraps a model; it may still be built or changed, but not removed while audio runs. */
    public PhysicalModelStepper(PhysicalModel model) {
        this(model, "a tactus.audio.PhysicalModelStepper plays it and sets its rate");
    }

    /**
     * Wraps a model for a driver that dictates its rate.
     *
     * @param rateHolder what {@code setSimRate} names when it refuses a change (its {@code toString()})
     */
    public PhysicalModelStepper(PhysicalModel model, Object rateHolder) {
        if (model == null) {
            throw new IllegalArgumentException("PhysicalModelStepper: the model must not be null");
        }
        if (rateHolder == null) {
            throw new IllegalArgumentException("PhysicalModelStepper: the rate holder must not be null");
        }
        this.model = model;
        this.realUnits = model.getParamSystem() == paramSystem.REAL_UNITS;
        this.rate = model.getSimRate();
        this.rateHolder = rateHolder;
        AudioHelper.ensureStarted();   // from this (the sketch's) thread, before an audio thread needs it
        model.beginRealtimeStepping();
        this.rateSetter = model.holdSimRate(rateHolder);
    }

    /** A lock that is never contended: realtime stepping needs none around a sample. */
    private static final java.util.concurrent.locks.Lock NO_LOCK = new NoLock();

    /** {@return the wrapped model} */
    public PhysicalModel model() {
        return model;
    }

    @Override
    public int stepRate() {
        return rate;
    }

    @Override
    public void setStepRate(int stepsPerSecond) {
        if (stepsPerSecond != model.getSimRate()) {
            rateSetter.accept(stepsPerSecond);
        }
        rate = stepsPerSecond;
    }

    /**
     * One step on the audio thread, which takes the stepping role first, whoever stepped the model before. If the
     * realtime mode has ended while the model is played ({@code endRealtimeStepping()} from a DivergenceListener or
     * another thread), the step runs in locked mode and the {@link AudioHelper} thread is asked to begin the mode
     * again and hold the rate again: in locked mode the audio thread would wait for the model's lock behind the
     * sketch's threads and analyse stability itself, the gaps of docs/audio.md, "Audio under load".
     */
    @Override
    public void step() {
        claimStepping();
        model.computeStep();
    }

    /**
     * The block's steps and reads in one call to the model ({@link PhysicalModel#computeNStepsRecording}): the model
     * is entered once, and other threads' changes land before the block's first step.
     */
    @Override
    public int stepRecording(int n, int[] handles, int[] axes, int count, double[] out) {
        claimStepping();
        Mass[] ms = recordMasses;
        if (ms.length != count) {
            ms = new Mass[count];   // only when the listening points change
            recordMasses = ms;
        }
        for (int i = 0; i < count; i++) {
            ms[i] = masses[handles[i]].mass;
        }
        return model.computeNStepsRecording(n, ms, axes, out);
    }

    /** Takes the stepping role, or asks the helper thread to begin realtime stepping again (see {@link #step()}). */
    private void claimStepping() {
        if (!model.takeRealtimeStepping() && !resuming) {
            resuming = true;
            AudioHelper.post(this::resumeRealtime);
        }
    }

    /** On the helper thread: puts the model back in realtime stepping and holds its rate for the driver again. */
    private void resumeRealtime() {
        try {
            model.beginRealtimeStepping();   // takes the model's lock, which ends a mode ended from inside a step
            rateSetter = model.holdSimRate(rateHolder);
            resumes++;
        } catch (RuntimeException e) {
            // the model refused (it is being torn down?): look again in a while, not at every sample
            LockSupport.parkNanos(250_000_000L);
        } finally {
            resuming = false;
        }
    }

    /** {@return how many times this stepper put the model back in realtime stepping after the mode ended} */
    public long realtimeResumes() {
        return resumes;
    }

    /**
     * {@return true while the model has diverged and is frozen (until {@code clearDivergence()}); a lock-free read
     *     ({@link PhysicalModel#isDivergedNow()}) that never waits for a thread holding the model}
     */
    @Override
    public boolean isHalted() {
        return model.isDivergedNow();
    }

    @Override
    public java.util.concurrent.locks.Lock sampleLock() {
        return NO_LOCK;
    }

    /**
     * Enters the model once for the whole sample ({@link PhysicalModel#beginRealtimeCalls()}): the step and the reads
     * of the sample then enter nothing. When that is refused (locked mode, the mode ending, another active owner) the
     * sample's calls enter one by one, as before, and {@link #step()} claims the model.
     */
    @Override
    public void beginSample() {
        inSample = model.beginRealtimeCalls();
    }

    @Override
    public void endSample() {
        if (inSample) {
            inSample = false;
            model.endRealtimeCalls();
        }
    }

    // ------------------------------------------------------------------ setup (the sketch's thread)

    @Override
    public int resolveMass(String name) {
        Mass m = model.getMass(name);
        for (int i = 0; i < massCount; i++) {
            if (masses[i].name.equals(name)) {
                masses[i].mass = m;
                return i;
            }
        }
        if (massCount == masses.length) {
            masses = Arrays.copyOf(masses, massCount * 2);
        }
        masses[massCount] = new MassSlot(name, m);
        return massCount++;
    }

    @Override
    public double massPositionForSetup(int mass, int axis) {
        Vect3D p = masses[mass].mass.getPosition(new Vect3D());
        return axis == X ? p.x : axis == Y ? p.y : p.z;
    }

    @Override
    public int resolveLink(String name, boolean withForce) {
        if (!model.linkExists(name)) {
            throw new IllegalArgumentException("resolveLink(\"" + name + "\"): no interaction with this name");
        }
        int rule = ruleFor(name, withForce);
        if (rule == RULE_UNSUPPORTED) {
            throw new IllegalArgumentException("resolveLink(\"" + name + "\"): cannot listen to the force of a "
                    + model.getLinkTypeAt(model.getLinkIndex(name)) + "; listen to its elongation instead");
        }
        if (linkCount == links.length) {
            links = Arrays.copyOf(links, linkCount * 2);
        }
        links[linkCount] = new LinkSlot(name, withForce, rule, model.getLinkElongation(name));
        return linkCount++;
    }

    /** @return how the tension of a link is read, or RULE_UNSUPPORTED; allocates nothing. */
    private int ruleFor(String name, boolean withForce) {
        if (!withForce) {
            return RULE_ALWAYS;
        }
        // the kind's descriptor says how its tension reads
        linkModuleType type = model.getLinkTypeAt(model.getLinkIndex(name));
        if (!type.hasReadableTension()) {
            return RULE_UNSUPPORTED;
        }
        return type.actsOnlyCompressed() ? RULE_COMPRESSED : type.actsOnlyStretched() ? RULE_STRETCHED : RULE_ALWAYS;
    }

    @Override
    public int resolveAvatar(String name) {
        String type = model.getMatTypeAt(indexOfMass(name)).name();
        if (!"HapticInput3D".equals(type)) {
            throw new IllegalArgumentException("resolveAvatar(\"" + name + "\"): not a HapticInput3D, this is a " + type);
        }
        for (int i = 0; i < avatarCount; i++) {
            if (avatars[i].equals(name)) {
                return i;
            }
        }
        if (avatarCount == avatars.length) {
            avatars = Arrays.copyOf(avatars, avatarCount * 2);
        }
        avatars[avatarCount] = name;
        return avatarCount++;
    }

    private int indexOfMass(String name) {
        int i = model.getMatIndex(name);
        if (i < 0) {
            throw new IllegalArgumentException("resolveAvatar(\"" + name + "\"): no mass with this name");
        }
        return i;
    }

    // ------------------------------------------------------------------ per sample (the audio thread)

    @Override
    public double massPosition(int mass, int axis) {
        Vect3D p = masses[mass].mass.getPosition(audioScratch);
        return axis == X ? p.x : axis == Y ? p.y : p.z;
    }

    @Override
    public double linkElongation(int link) {
        return model.getLinkElongation(links[link].name);
    }

    @Override
    public double linkTension(int link) {
        LinkSlot s = links[link];
        String name = s.name;
        double e = model.getLinkElongation(name);
        double de = e - s.lastElongation;
        s.lastElongation = e;
        int rule = s.rule;
        if ((rule == RULE_COMPRESSED && e >= 0) || (rule == RULE_STRETCHED && e <= 0)) {
            return 0;
        }
        double rateOfElongation = realUnits ? de * rate : de;
        return model.getLinkStiffness(name) * e + model.getLinkDamping(name) * rateOfElongation;
    }

    @Override
    public void setAvatarTarget(int avatar, double x, double y, double z) {
        model.setHapticPosition(avatars[avatar], audioTarget.set(x, y, z));
    }

    @Override
    public void takeAvatarForce(int avatar, double[] out) {
        Vect3D f = model.getHapticForce(avatars[avatar], audioScratch);
        out[0] = f.x;
        out[1] = f.y;
        out[2] = f.z;
    }

    // ------------------------------------------------------------------ finding a removed element again (audio thread, rarely)

    @Override
    public boolean reattachMass(int mass) {
        MassSlot s = masses[mass];
        if (s.mass.isValid()) {
            return true;
        }
        if (!model.matExists(s.name)) {
            return false;
        }
        s.mass = model.getMass(s.name);
        return true;
    }

    @Override
    public boolean reattachLink(int link) {
        LinkSlot s = links[link];
        if (!model.linkExists(s.name)) {
            return false;
        }
        int rule = ruleFor(s.name, s.withForce);
        if (rule == RULE_UNSUPPORTED) {
            return false;
        }
        s.rule = rule;
        s.lastElongation = model.getLinkElongation(s.name);
        return true;
    }

    @Override
    public boolean reattachAvatar(int avatar) {
        int i = model.getMatIndex(avatars[avatar]);
        return i >= 0 && "HapticInput3D".equals(model.getMatTypeAt(i).name());
    }

    /** The no-op lock of {@link #sampleLock()}. */
    private static final class NoLock implements java.util.concurrent.locks.Lock {
        @Override
        public void lock() {
        }

        @Override
        public void lockInterruptibly() {
        }

        @Override
        public boolean tryLock() {
            return true;
        }

        @Override
        public boolean tryLock(long time, java.util.concurrent.TimeUnit unit) {
            return true;
        }

        @Override
        public void unlock() {
        }

        @Override
        public java.util.concurrent.locks.Condition newCondition() {
            throw new UnsupportedOperationException("PhysicalModelStepper: no conditions on the sample lock");
        }
    }
}
