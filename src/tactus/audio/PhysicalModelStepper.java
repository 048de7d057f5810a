package tactus.audio;

import java.util.Arrays;
import tactus.Mass;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * The one adapter from {@link SteppedModel} to the public {@link PhysicalModel} API. Creating it puts the model in
 * realtime stepping ({@link PhysicalModel#beginRealtimeStepping()}): the thread that steps it (Minim's audio thread)
 * takes no lock and never waits for another thread; other threads' changes are queued and applied between two
 * samples. Names are resolved once into handles; the per-sample methods reuse scratch vectors and allocate nothing
 * ({@code PhyUGenAllocationTest}). Interaction reads look the name up in a hash table per call.
 */
public final class PhysicalModelStepper implements SteppedModel {
    private final PhysicalModel model;
    private final boolean realUnits;
    private final Vect3D scratch = new Vect3D();
    private final Vect3D target = new Vect3D();
    private Mass[] masses = new Mass[4];
    private int massCount;
    private String[] links = new String[4];
    private int[] linkRule = new int[4];
    private double[] lastElongation = new double[4];
    private int linkCount;
    private String[] avatars = new String[2];
    private int avatarCount;
    private int rate;

    private static final int RULE_ALWAYS = 0;
    private static final int RULE_COMPRESSED = 1;
    private static final int RULE_STRETCHED = 2;

    /** Wraps a model; it may still be built or changed, but not removed while audio runs. */
    public PhysicalModelStepper(PhysicalModel model) {
        if (model == null) {
            throw new IllegalArgumentException("PhysicalModelStepper: the model must not be null");
        }
        this.model = model;
        this.realUnits = model.getParamSystem() == paramSystem.REAL_UNITS;
        this.rate = model.getSimRate();
        model.beginRealtimeStepping();
    }

    /** A lock that is never contended: realtime stepping needs none around a sample. */
    private static final java.util.concurrent.locks.Lock NO_LOCK = new NoLock();

    /** @return the wrapped model. */
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
            model.setSimRate(stepsPerSecond);
        }
        rate = stepsPerSecond;
    }

    @Override
    public void step() {
        model.computeStep();
    }

    @Override
    public java.util.concurrent.locks.Lock sampleLock() {
        return NO_LOCK;
    }

    @Override
    public int resolveMass(String name) {
        Mass m = model.getMass(name);
        for (int i = 0; i < massCount; i++) {
            if (masses[i] == m) {
                return i;
            }
        }
        if (massCount == masses.length) {
            masses = Arrays.copyOf(masses, massCount * 2);
        }
        masses[massCount] = m;
        return massCount++;
    }

    @Override
    public int resolveLink(String name, boolean withForce) {
        if (!model.linkExists(name)) {
            throw new IllegalArgumentException("resolveLink(\"" + name + "\"): no interaction with this name");
        }
        int rule = RULE_ALWAYS;
        if (withForce) {
            String type = model.getLinkTypeAt(model.getLinkIndex(name)).name();
            switch (type) {
                case "Spring3D":
                case "Damper3D":
                case "SpringDamper3D":
                case "SpringDamper1D":
                    rule = RULE_ALWAYS;
                    break;
                case "Contact3D":
                    rule = RULE_COMPRESSED;
                    break;
                case "Rope3D":
                case "Bubble3D":
                    rule = RULE_STRETCHED;
                    break;
                default:
                    throw new IllegalArgumentException("resolveLink(\"" + name + "\"): cannot listen to the force of a "
                            + type + "; listen to its elongation instead");
            }
        }
        if (linkCount == links.length) {
            links = Arrays.copyOf(links, linkCount * 2);
            linkRule = Arrays.copyOf(linkRule, linkCount * 2);
            lastElongation = Arrays.copyOf(lastElongation, linkCount * 2);
        }
        links[linkCount] = name;
        linkRule[linkCount] = rule;
        lastElongation[linkCount] = model.getLinkElongation(name);
        return linkCount++;
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

    @Override
    public double massPosition(int mass, int axis) {
        Vect3D p = masses[mass].getPosition(scratch);
        return axis == X ? p.x : axis == Y ? p.y : p.z;
    }

    @Override
    public double linkElongation(int link) {
        return model.getLinkElongation(links[link]);
    }

    @Override
    public double linkTension(int link) {
        String name = links[link];
        double e = model.getLinkElongation(name);
        double de = e - lastElongation[link];
        lastElongation[link] = e;
        int rule = linkRule[link];
        if ((rule == RULE_COMPRESSED && e >= 0) || (rule == RULE_STRETCHED && e <= 0)) {
            return 0;
        }
        double rateOfElongation = realUnits ? de * rate : de;
        return model.getLinkStiffness(name) * e + model.getLinkDamping(name) * rateOfElongation;
    }

    @Override
    public void setAvatarTarget(int avatar, double x, double y, double z) {
        model.setHapticPosition(avatars[avatar], target.set(x, y, z));
    }

    @Override
    public void takeAvatarForce(int avatar, double[] out) {
        Vect3D f = model.getHapticForce(avatars[avatar], scratch);
        out[0] = f.x;
        out[1] = f.y;
        out[2] = f.z;
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
