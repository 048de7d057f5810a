package tactus;

import java.util.Set;
import processing.core.PVector;
import tactus.engine.Engine;
import tactus.engine.EnergyMeter;
import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.engine.StabilityAnalyzer;
import tactus.engine.StabilityReport;
import tactus.engine.StepPlan;

/**
 * A mass-interaction physical model: masses and interactions addressed by name, simulated at a
 * fixed rate with the explicit two-phase scheme of the paper (masses move, then interactions
 * compute forces, with a one-step force delay).
 *
 * <p>Build the model with the {@code add...} methods, call {@link #init()}, then advance it with
 * {@link #draw_physics()} once per frame, or with {@link #computeStep()} /
 * {@link #computeNSteps(int)} from a haptic or audio loop. Parameters are given in the unit
 * system chosen at construction ({@link paramSystem}); initial velocities are always in units
 * per second. Bad arguments raise an {@link IllegalArgumentException} that names the element
 * and the value, and leave the model unchanged.
 *
 * <p>All methods are thread-safe: they synchronise on {@link #getLock()}.
 */
public class PhysicalModel {
    /** The library version. */
    public static final String VERSION = "0.1.0";

    private final Object lock = new Object();
    private final Engine engine = new Engine();
    private final Registry mats = new Registry();
    private final Registry links = new Registry();
    private final Subsets matSubsets = new Subsets();
    private final Subsets linkSubsets = new Subsets();
    private final paramSystem system;
    private final UnitScale units;
    private final double[] tmp = new double[3];
    private int simRate;
    private int dispRate;
    /** Fractional step carried between frames, in units of 1/dispRate steps (exact integer arithmetic). */
    private long residue;
    private double gravity;
    private final Vect3D gravityDir = new Vect3D(0, 0, 1);
    private double friction;
    private Mass[] massHandles = new Mass[16];
    private Interaction[] linkHandles = new Interaction[16];
    private boolean initialized;
    private StabilityPolicy stabilityPolicy = StabilityPolicy.WARN;
    private int maxContacts = StabilityAnalyzer.DEFAULT_MAX_CONTACTS;
    private int deferAnalysis;
    private String lastWarning;
    private DivergenceListener divergenceListener;
    /** Contact groups by mass-subset name, in creation order, with their engine group ids. */
    private final java.util.LinkedHashMap<String, Integer> contactGroups = new java.util.LinkedHashMap<>();
    private boolean divergenceNotified;

    /**
     * Creates an empty model.
     *
     * @param simRate simulation steps per second (Hz), &gt; 0
     * @param displayRate frames per second at which {@link #draw_physics()} is called, &gt; 0
     * @param system the unit system of every parameter
     */
    public PhysicalModel(int simRate, int displayRate, paramSystem system) {
        if (simRate <= 0) {
            throw new IllegalArgumentException("PhysicalModel: simRate must be > 0 Hz, got " + simRate);
        }
        if (displayRate <= 0) {
            throw new IllegalArgumentException("PhysicalModel: displayRate must be > 0 Hz, got " + displayRate);
        }
        if (system == null) {
            throw new IllegalArgumentException("PhysicalModel: the unit system must not be null");
        }
        this.simRate = simRate;
        this.dispRate = displayRate;
        this.system = system;
        this.units = new UnitScale(system, simRate);
    }

    /** Creates an empty model in algorithmic units. */
    public PhysicalModel(int simRate, int displayRate) {
        this(simRate, displayRate, paramSystem.ALGO_UNITS);
    }

    /** Creates an empty model in algorithmic units, displayed at 30 frames per second. */
    public PhysicalModel(int simRate) {
        this(simRate, 30, paramSystem.ALGO_UNITS);
    }

    /** Creates an empty model in the given units, displayed at 30 frames per second. */
    public PhysicalModel(int simRate, paramSystem system) {
        this(simRate, 30, system);
    }

    /** @return the library version string. */
    public static String version() {
        return VERSION;
    }

    /** @return the object every method of this model synchronises on. */
    public Object getLock() {
        return lock;
    }

    /** @return the unit system of this model. */
    public paramSystem getParamSystem() {
        return system;
    }

    // =================================================================== rates and stepping

    /** @return the simulation rate, in steps per second. */
    public int getSimRate() {
        synchronized (lock) {
            return simRate;
        }
    }

    /**
     * Changes the simulation rate. In REAL_UNITS every coefficient is re-derived so the model
     * keeps describing the same physical system, and velocities (in units per second) are kept.
     * In ALGO_UNITS coefficients are per step and stay as they are.
     *
     * @param rate steps per second, &gt; 0
     */
    public void setSimRate(int rate) {
        if (rate <= 0) {
            throw new IllegalArgumentException("setSimRate: the rate must be > 0 Hz, got " + rate);
        }
        synchronized (lock) {
            int old = simRate;
            applyRate(rate);
            analyzeAfterChange(() -> applyRate(old));
        }
    }

    private void applyRate(int rate) {
        double ratio = (double) simRate / rate;
        simRate = rate;
        residue = 0;
        if (units.isReal() && ratio != 1.0) {
            rescale(ratio);
        }
        units.setRate(rate);
        applyMedium();
    }

    private void rescale(double ratio) {
        double r2 = ratio * ratio;
        for (int id : mats.ids()) {
            if (engine.massKind(id).isOscillator()) {
                engine.setOscillator(id, engine.oscStiffness(id) * r2, engine.oscDamping(id) * ratio);
            }
        }
        for (int id : links.ids()) {
            engine.setLinkParams(id, engine.linkStiffness(id) * r2, engine.linkDamping(id) * ratio,
                    engine.linkLength(id));
            if (engine.linkKind(id) == LinkKind.ATTRACTOR3D) {
                engine.setLinkAux(id, engine.linkAux(id) * r2);
            }
        }
        engine.rescaleTime(ratio);
    }

    /** @return the display rate, in frames per second. */
    public int getDisplayRate() {
        synchronized (lock) {
            return dispRate;
        }
    }

    /** Sets the display rate used by {@link #draw_physics()}, in frames per second (&gt; 0). */
    public void setDisplayRate(int rate) {
        if (rate <= 0) {
            throw new IllegalArgumentException("setDisplayRate: the rate must be > 0 Hz, got " + rate);
        }
        synchronized (lock) {
            dispRate = rate;
            residue = 0;
        }
    }

    /**
     * Prepares the model for simulation: compiles the scene into its step plan. Call it once
     * after building; later topology changes are compiled automatically before the next step.
     */
    public void init() {
        synchronized (lock) {
            engine.compile();
            initialized = true;
            lastWarning = null;
            analyzeAfterChange(null);
        }
    }

    /**
     * Advances the model by one display frame: {@code floor(simRate / displayRate + r)} steps,
     * where the fractional remainder r is carried to the next frame.
     *
     * @return the number of steps run
     */
    public int draw_physics() {
        synchronized (lock) {
            long total = simRate + residue;
            int n = (int) (total / dispRate);
            residue = total % dispRate;
            engine.step(n);
            checkDivergence();
            return n;
        }
    }

    /** Runs one simulation step. */
    public void computeStep() {
        synchronized (lock) {
            engine.step(1);
            checkDivergence();
        }
    }

    /** Runs {@code n} simulation steps (n &ge; 0). */
    public void computeNSteps(int n) {
        if (n < 0) {
            throw new IllegalArgumentException("computeNSteps: the step count must be >= 0, got " + n);
        }
        synchronized (lock) {
            engine.step(n);
            checkDivergence();
        }
    }

    /**
     * Lets large models step on several threads (1, the default, keeps everything on the calling thread).
     * Only models of at least 20,000 elements (masses plus interactions) stepped several steps at a time
     * ({@link #computeNSteps(int)}, {@link #draw_physics()}) use them; results are bit-identical to one
     * thread. Use at most the number of cores left free by the audio and haptic threads.
     *
     * @param threads 1 or more
     */
    public void setThreads(int threads) {
        if (threads < 1) {
            throw new IllegalArgumentException("setThreads: the thread count must be >= 1, got " + threads);
        }
        synchronized (lock) {
            engine.setThreads(threads);
        }
    }

    /** @return the number of threads large models may use. */
    public int getThreads() {
        synchronized (lock) {
            return engine.threads();
        }
    }

    /** @return the number of steps simulated since the model was created. */
    public long getStepCount() {
        synchronized (lock) {
            return engine.stepCount();
        }
    }

    /** @return the names of the kernels the compiled step plan runs, one per kind present, in order. */
    public String[] getPlanKernels() {
        synchronized (lock) {
            return engine.plan().kernelNames();
        }
    }

    // =================================================================== global medium

    /**
     * Sets the gravity magnitude (REAL_UNITS: m/s^2). Masses accelerate along minus the gravity
     * direction, so with the default direction (0, 0, 1) they fall toward -z.
     */
    public void setGravity(double magnitude) {
        Check.finite("setGravity", "gravity", "magnitude", magnitude);
        synchronized (lock) {
            gravity = magnitude;
            applyMedium();
        }
    }

    /** @return the gravity magnitude in model units. */
    public double getGravity() {
        synchronized (lock) {
            return gravity;
        }
    }

    /** Sets the gravity direction ("up"); it is normalised. Masses accelerate along its opposite. */
    public void setGravityDirection(Vect3D direction) {
        Check.vector("setGravityDirection", "gravity", "direction", direction);
        double big = Math.max(Math.abs(direction.x), Math.max(Math.abs(direction.y), Math.abs(direction.z)));
        if (big == 0) {
            throw Check.fail("setGravityDirection", "gravity", "direction must not be the zero vector");
        }
        Vect3D unit = new Vect3D(direction).div(big);
        unit.div(unit.norm());
        synchronized (lock) {
            gravityDir.set(unit);
            applyMedium();
        }
    }

    /** @return a copy of the normalised gravity direction. */
    public Vect3D getGravityDirection() {
        synchronized (lock) {
            return new Vect3D(gravityDir);
        }
    }

    /** Sets the air friction applied to every moving mass (REAL_UNITS: N·s/m), &ge; 0 in normal use. */
    public void setFriction(double f) {
        Check.finite("setFriction", "friction", "friction", f);
        synchronized (lock) {
            double old = friction;
            friction = f;
            applyMedium();
            analyzeAfterChange(() -> {
                friction = old;
                applyMedium();
            });
        }
    }

    /** @return the air friction in model units. */
    public double getFriction() {
        synchronized (lock) {
            return friction;
        }
    }

    private void applyMedium() {
        double g = units.accelerationIn(gravity);
        engine.setGravity(-g * gravityDir.x, -g * gravityDir.y, -g * gravityDir.z);
        engine.setFriction(units.dampingIn(friction));
    }

    // =================================================================== adding masses

    /**
     * Adds a free 3D mass subject to its links, air friction and gravity.
     *
     * @param name unique mass name
     * @param mass inertia (REAL_UNITS: kg), finite and &gt; 0
     * @param initPos initial position
     * @param initVel initial velocity, in units per second
     * @return the new module's handle
     */
    public Mass3D addMass3D(String name, double mass, Vect3D initPos, Vect3D initVel) {
        return (Mass3D) addMass("addMass3D", MassKind.MASS3D, name, mass, initPos, initVel, 0, 0, 1);
    }

    /** Adds a mass that moves in its initial z plane only (see {@link #addMass3D}). */
    public Mass2DPlane addMass2DPlane(String name, double mass, Vect3D initPos, Vect3D initVel) {
        return (Mass2DPlane) addMass("addMass2DPlane", MassKind.MASS2D_PLANE, name, mass, initPos, initVel, 0, 0, 1);
    }

    /** Adds a mass that moves along z only (see {@link #addMass3D}). */
    public Mass1D addMass1D(String name, double mass, Vect3D initPos, Vect3D initVel) {
        return (Mass1D) addMass("addMass1D", MassKind.MASS1D, name, mass, initPos, initVel, 0, 0, 1);
    }

    /** Adds a fixed point in 3D. */
    public Ground3D addGround3D(String name, Vect3D initPos) {
        return (Ground3D) addMass("addGround3D", MassKind.GROUND3D, name, 1, initPos, new Vect3D(), 0, 0, 1);
    }

    /** Adds a fixed point for 1D models. */
    public Ground1D addGround1D(String name, Vect3D initPos) {
        return (Ground1D) addMass("addGround1D", MassKind.GROUND1D, name, 1, initPos, new Vect3D(), 0, 0, 1);
    }

    /**
     * Adds a 3D oscillator: a mass tied to its initial position by an internal spring K and
     * damper Z (REAL_UNITS: N/m and N·s/m), also subject to air friction and gravity.
     */
    public Osc3D addOsc3D(String name, double mass, double K, double Z, Vect3D initPos, Vect3D initVel) {
        return (Osc3D) addMass("addOsc3D", MassKind.OSC3D, name, mass, initPos, initVel, K, Z, 1);
    }

    /**
     * Adds a 3D oscillator tuned by its pitch and decay: its stiffness and damping are chosen by exact pole
     * matching at the current simulation rate, so it rings at exactly {@code freqHz} and loses 60 dB in exactly
     * {@code t60} seconds (air friction included), with none of the scheme's frequency warping. Retune it with
     * {@link #tuneOsc} after changing the simulation rate.
     *
     * @param freqHz pitch in Hz, below half the simulation rate
     * @param t60 60 dB decay time in seconds, &gt; 0 ({@code Double.POSITIVE_INFINITY} for none)
     */
    public Osc3D addOsc3DTuned(String name, double mass, double freqHz, double t60, Vect3D initPos, Vect3D initVel) {
        double[] kz = tunedCoefficients("addOsc3DTuned", name, mass, freqHz, t60);
        return addOsc3D(name, mass, kz[0], kz[1], initPos, initVel);
    }

    /** Adds a 1D oscillator tuned by its pitch and decay (see {@link #addOsc3DTuned}). */
    public Osc1D addOsc1DTuned(String name, double mass, double freqHz, double t60, Vect3D initPos, Vect3D initVel) {
        double[] kz = tunedCoefficients("addOsc1DTuned", name, mass, freqHz, t60);
        return addOsc1D(name, mass, kz[0], kz[1], initPos, initVel);
    }

    /** Retunes an oscillator to ring at exactly {@code freqHz} and decay by 60 dB in {@code t60} seconds. */
    public void tuneOsc(String name, double freqHz, double t60) {
        synchronized (lock) {
            int id = massId("tuneOsc", name);
            requireOsc("tuneOsc", id);
            double[] kz = tunedCoefficients("tuneOsc", name, engine.mass(id), freqHz, t60);
            setOscOf("tuneOsc", id, kz[0], kz[1]);
        }
    }

    /** @return the frequency (Hz) at which an oscillator actually rings in this scheme, friction included. */
    public double getOscFrequency(String name) {
        synchronized (lock) {
            int id = massId("getOscFrequency", name);
            requireOsc("getOscFrequency", id);
            double m = engine.mass(id);
            return tactus.engine.Tuning.discreteFrequency(engine.oscStiffness(id) / m,
                    (engine.oscDamping(id) + engine.friction()) / m, simRate);
        }
    }

    /** @return the 60 dB decay time (seconds) of an oscillator in this scheme, friction included. */
    public double getOscT60(String name) {
        synchronized (lock) {
            int id = massId("getOscT60", name);
            requireOsc("getOscT60", id);
            return tactus.engine.Tuning.decayTime60((engine.oscDamping(id) + engine.friction()) / engine.mass(id),
                    simRate);
        }
    }

    /** @return {K, Z} in model units for a pole-matched oscillator of the given mass, air friction deducted. */
    private double[] tunedCoefficients(String op, String name, double mass, double freqHz, double t60) {
        Check.positive(op, String.valueOf(name), "mass", mass);
        if (!(freqHz > 0) || !(freqHz < simRate / 2.0)) {
            throw Check.fail(op, String.valueOf(name), "freqHz must be in (0, " + simRate / 2.0
                    + ") Hz at this simulation rate, got " + freqHz);
        }
        if (!(t60 > 0)) {
            throw Check.fail(op, String.valueOf(name), "t60 must be > 0 s, got " + t60);
        }
        synchronized (lock) {
            double[] r = tactus.engine.Tuning.oscillatorCoefficients(freqHz, t60, simRate);
            double k = r[0] * mass;
            double z = r[1] * mass - engine.friction();
            if (z < 0) {
                throw Check.fail(op, String.valueOf(name), "air friction alone already decays faster than t60 = "
                        + t60 + " s; use a longer t60 or less friction");
            }
            return new double[] {units.stiffnessOut(k), units.dampingOut(z)};
        }
    }

    /** Adds an oscillator that moves along z only (see {@link #addOsc3D}). */
    public Osc1D addOsc1D(String name, double mass, double K, double Z, Vect3D initPos, Vect3D initVel) {
        return (Osc1D) addMass("addOsc1D", MassKind.OSC1D, name, mass, initPos, initVel, K, Z, 1);
    }

    /**
     * Adds the haptic avatar: its position follows the device position through an exponentially
     * weighted moving average of weight 1/smoothing per step, and it accumulates the force the
     * model applies to it until {@link #getHapticForce(String)} reads it.
     *
     * @param smoothing EWMA length in steps, &ge; 1 (1 means no smoothing)
     */
    public HapticInput3D addHapticInput3D(String name, Vect3D initPos, int smoothing) {
        return (HapticInput3D) addMass("addHapticInput3D", MassKind.HAPTIC_INPUT3D, name, 1, initPos,
                new Vect3D(), 0, 0, smoothing);
    }

    /** Adds a kinematic position driver that follows its target through an EWMA (weight 1/smoothing). */
    public PosInput3D addPosInput3D(String name, Vect3D initPos, int smoothing) {
        return (PosInput3D) addMass("addPosInput3D", MassKind.POS_INPUT3D, name, 1, initPos,
                new Vect3D(), 0, 0, smoothing);
    }

    private Mass addMass(String op, MassKind kind, String name, double m, Vect3D pos, Vect3D vel,
                         double K, double Z, int smoothing) {
        Check.name(op, name);
        Check.vector(op, name, "initPos", pos);
        Check.vector(op, name, "initVel", vel);
        if (kind.isInertial()) {
            Check.positive(op, name, "mass", m);
        }
        if (kind.isOscillator()) {
            Check.finite(op, name, "K", K);
            Check.finite(op, name, "Z", Z);
        }
        if (kind.isInput() && smoothing < 1) {
            throw Check.fail(op, name, "smoothing must be >= 1 step, got " + smoothing);
        }
        synchronized (lock) {
            if (mats.id(name) >= 0) {
                throw Check.fail(op, name, "a mass with this name already exists");
            }
            int id = engine.addMass(kind, m, pos.x, pos.y, pos.z,
                    units.velocityIn(vel.x), units.velocityIn(vel.y), units.velocityIn(vel.z));
            if (kind.isOscillator()) {
                engine.setOscillator(id, units.stiffnessIn(K), units.dampingIn(Z));
            }
            if (kind.isInput()) {
                engine.setInputWeight(id, 1.0 / smoothing);
            }
            mats.add(name, id);
            Mass h = registerMass(id, kind);
            analyzeAfterChange(() -> removeMassId(id));
            return h;
        }
    }

    private Mass registerMass(int id, MassKind kind) {
        if (id >= massHandles.length) {
            massHandles = java.util.Arrays.copyOf(massHandles, Math.max(id + 1, massHandles.length * 2));
        }
        Mass h = Mass.create(this, id, kind);
        massHandles[id] = h;
        return h;
    }

    // =================================================================== adding interactions

    /** Adds a spring: force -K (d - dist) along the line between the masses (REAL_UNITS: K in N/m). */
    public Spring3D addSpring3D(String name, double dist, double K, String m1, String m2) {
        return (Spring3D) addLink("addSpring3D", LinkKind.SPRING3D, name, m1, m2, K, 0, dist);
    }

    /** Adds a spring between two mass handles (see {@link #addSpring3D(String, double, double, String, String)}). */
    public Spring3D addSpring3D(String name, double dist, double K, Mass m1, Mass m2) {
        return addSpring3D(name, dist, K, nameOf(m1), nameOf(m2));
    }

    /** Adds a damper: force -Z (d(n) - d(n-1)) along the line between the masses (REAL_UNITS: N·s/m). */
    public Damper3D addDamper3D(String name, double Z, String m1, String m2) {
        return (Damper3D) addLink("addDamper3D", LinkKind.DAMPER3D, name, m1, m2, 0, Z, 0);
    }

    /** Adds a damper between two mass handles. */
    public Damper3D addDamper3D(String name, double Z, Mass m1, Mass m2) {
        return addDamper3D(name, Z, nameOf(m1), nameOf(m2));
    }

    /** Adds a spring and damper in parallel, with rest length {@code dist}. */
    public SpringDamper3D addSpringDamper3D(String name, double dist, double K, double Z, String m1, String m2) {
        return (SpringDamper3D) addLink("addSpringDamper3D", LinkKind.SPRING_DAMPER3D, name, m1, m2, K, Z, dist);
    }

    /** Adds a spring-damper between two mass handles. */
    public SpringDamper3D addSpringDamper3D(String name, double dist, double K, double Z, Mass m1, Mass m2) {
        return addSpringDamper3D(name, dist, K, Z, nameOf(m1), nameOf(m2));
    }

    /** Adds a spring-damper that acts along z only, on the signed difference z1 - z2 with rest value {@code dist}. */
    public SpringDamper1D addSpringDamper1D(String name, double dist, double K, double Z, String m1, String m2) {
        return (SpringDamper1D) addLink("addSpringDamper1D", LinkKind.SPRING_DAMPER1D, name, m1, m2, K, Z, dist);
    }

    /** Adds a 1D spring-damper between two mass handles. */
    public SpringDamper1D addSpringDamper1D(String name, double dist, double K, double Z, Mass m1, Mass m2) {
        return addSpringDamper1D(name, dist, K, Z, nameOf(m1), nameOf(m2));
    }

    /** Adds a rope: a spring-damper that acts only while the masses are farther apart than {@code dist}. */
    public Rope3D addRope3D(String name, double dist, double K, double Z, String m1, String m2) {
        return (Rope3D) addLink("addRope3D", LinkKind.ROPE3D, name, m1, m2, K, Z, dist);
    }

    /** Adds a rope between two mass handles. */
    public Rope3D addRope3D(String name, double dist, double K, double Z, Mass m1, Mass m2) {
        return addRope3D(name, dist, K, Z, nameOf(m1), nameOf(m2));
    }

    /**
     * Adds a contact: a spring-damper that acts only while the masses are closer than the threshold {@code dist}.
     * At distance exactly 0 it has no direction to push along and exerts no force: masses resting exactly on
     * each other stay there until something separates them, and a pair whose paths cross at exactly d = 0 in a
     * step passes through. Adding a contact between two masses at exactly the same position prints a warning
     * naming the contact and the masses on {@code System.err}.
     */
    public Contact3D addContact3D(String name, double dist, double K, double Z, String m1, String m2) {
        return (Contact3D) addLink("addContact3D", LinkKind.CONTACT3D, name, m1, m2, K, Z, dist);
    }

    /** Adds a contact between two mass handles. */
    public Contact3D addContact3D(String name, double dist, double K, double Z, Mass m1, Mass m2) {
        return addContact3D(name, dist, K, Z, nameOf(m1), nameOf(m2));
    }

    /** Adds a bubble: keeps m1 within radius {@code dist} of m2 with a spring-damper acting only outside it. */
    public Bubble3D addBubble3D(String name, double dist, double K, double Z, String m1, String m2) {
        return (Bubble3D) addLink("addBubble3D", LinkKind.BUBBLE3D, name, m1, m2, K, Z, dist);
    }

    /** Adds a bubble between two mass handles. */
    public Bubble3D addBubble3D(String name, double dist, double K, double Z, Mass m1, Mass m2) {
        return addBubble3D(name, dist, K, Z, nameOf(m1), nameOf(m2));
    }

    /**
     * Adds a one-sided contact between a mass and an axis-aligned plane. The plane is normal to
     * axis {@code orientation} (0 = x, 1 = y, 2 = z) at coordinate {@code pos}; while the mass
     * coordinate q is below {@code pos + l0} it is pushed back with {@code -K t - Z dq}, where
     * {@code t = q - pos - l0}.
     */
    public PlaneContact3D addPlaneContact(String name, double l0, double K, double Z, int orientation,
                                          double pos, String m1) {
        return (PlaneContact3D) addLink("addPlaneContact", LinkKind.PLANE_CONTACT3D, name, m1, null, K, Z, l0,
                pos, orientation);
    }

    /** Adds a plane contact on a mass handle. */
    public PlaneContact3D addPlaneContact(String name, double l0, double K, double Z, int orientation,
                                          double pos, Mass m1) {
        return addPlaneContact(name, l0, K, Z, orientation, pos, nameOf(m1));
    }

    /**
     * Adds an inverse-square attractor: force -attr / d^2 between the masses while d &gt; dLim
     * (REAL_UNITS: attr in N·m^2). A negative factor repels.
     *
     * @param dLim limit distance, finite and &gt; 0: the force is unbounded as d goes to 0, so it is switched
     *             off inside dLim
     * @throws IllegalArgumentException naming the attractor and the value, when dLim &le; 0
     */
    public Attractor3D addAttractor3D(String name, double dLim, double attr, String m1, String m2) {
        return (Attractor3D) addLink("addAttractor3D", LinkKind.ATTRACTOR3D, name, m1, m2, 0, 0, dLim, attr, 0);
    }

    /** Adds an attractor between two mass handles. */
    public Attractor3D addAttractor3D(String name, double dLim, double attr, Mass m1, Mass m2) {
        return addAttractor3D(name, dLim, attr, nameOf(m1), nameOf(m2));
    }

    private Interaction addLink(String op, LinkKind kind, String name, String m1, String m2,
                                double K, double Z, double len) {
        return addLink(op, kind, name, m1, m2, K, Z, len, 0, 0);
    }

    private Interaction addLink(String op, LinkKind kind, String name, String m1, String m2,
                                double K, double Z, double len, double aux, int axis) {
        Check.name(op, name);
        String label = name;
        Check.finite(op, label, "K", K);
        Check.finite(op, label, "Z", Z);
        if (kind == LinkKind.PLANE_CONTACT3D) {
            Check.finite(op, label, "l0", len);
            Check.finite(op, label, "pos", aux);
            if (axis < 0 || axis > 2) {
                throw Check.fail(op, label, "orientation must be 0 (x), 1 (y) or 2 (z), got " + axis);
            }
        } else if (kind == LinkKind.ATTRACTOR3D) {
            Check.attractorLimit(op, label, len);
        } else {
            Check.nonNegative(op, label, "dist", len);
        }
        if (kind == LinkKind.ATTRACTOR3D) {
            Check.finite(op, label, "attr", aux);
        }
        synchronized (lock) {
            if (links.id(label) >= 0) {
                throw Check.fail(op, label, "an interaction with this name already exists");
            }
            int a = requireMass(op, label, m1);
            int b = kind.isSingleMass() ? a : requireMass(op, label, m2);
            if (!kind.isSingleMass() && a == b) {
                throw Check.fail(op, label, "cannot link mass \"" + m1 + "\" to itself");
            }
            int id;
            if (kind == LinkKind.PLANE_CONTACT3D) {
                id = engine.addPlaneContact(a, axis, aux, len, units.stiffnessIn(K), units.dampingIn(Z));
            } else if (kind == LinkKind.ATTRACTOR3D) {
                id = engine.addAttractor(a, b, len, units.forceIn(aux));
            } else {
                id = engine.addLink(kind, a, b, units.stiffnessIn(K), units.dampingIn(Z), len);
            }
            links.add(label, id);
            Interaction h = Interaction.create(this, id, kind);
            storeLinkHandle(id, h);
            analyzeAfterChange(() -> removeLinkId(id));
            if (kind == LinkKind.CONTACT3D && engine.linkDistance(id) == 0) {
                System.err.println(coincidentContactWarning(label, m1, m2));
            }
            return h;
        }
    }

    /** The warning printed once, when a Contact3D is added between two masses at exactly the same position. */
    static String coincidentContactWarning(String link, String m1, String m2) {
        return "Tactus: Contact3D \"" + link + "\" joins \"" + m1 + "\" and \"" + m2 + "\" at exactly the same"
                + " position: at distance 0 a contact has no direction to push along, so it exerts no force until"
                + " the masses separate";
    }

    private void storeLinkHandle(int id, Interaction h) {
        if (id >= linkHandles.length) {
            linkHandles = java.util.Arrays.copyOf(linkHandles, Math.max(id + 1, linkHandles.length * 2));
        }
        linkHandles[id] = h;
    }

    private int requireMass(String op, String element, String massName) {
        int id = mats.id(massName);
        if (id < 0) {
            throw Check.fail(op, element, "unknown mass \"" + massName + "\"");
        }
        return id;
    }

    private String nameOf(Mass m) {
        if (m == null) {
            throw new IllegalArgumentException("a mass handle must not be null");
        }
        if (m.model != this) {
            throw new IllegalArgumentException("mass \"" + m.getName() + "\" belongs to another model");
        }
        return m.getName();
    }

    // =================================================================== look-up

    /** @return true when a mass with this name exists. */
    public boolean matExists(String name) {
        synchronized (lock) {
            return mats.id(name) >= 0;
        }
    }

    /** @return true when an interaction with this name exists. */
    public boolean linkExists(String name) {
        synchronized (lock) {
            return links.id(name) >= 0;
        }
    }

    /** @return the number of masses. */
    public int getNumberOfMats() {
        synchronized (lock) {
            return mats.size();
        }
    }

    /** @return the number of interactions. */
    public int getNumberOfLinks() {
        synchronized (lock) {
            return links.size();
        }
    }

    /** @return the index of a mass in insertion order (indices shift down after removals), or -1. */
    public int getMatIndex(String name) {
        synchronized (lock) {
            int id = mats.id(name);
            return id < 0 ? -1 : mats.indexOf(id);
        }
    }

    /** @return the index of an interaction in insertion order, or -1. */
    public int getLinkIndex(String name) {
        synchronized (lock) {
            int id = links.id(name);
            return id < 0 ? -1 : links.indexOf(id);
        }
    }

    /** @return the handle of a mass by name. */
    public Mass getMass(String name) {
        synchronized (lock) {
            return massHandles[massId("getMass", name)];
        }
    }

    /** @return the handle of an interaction by name. */
    public Interaction getInteraction(String name) {
        synchronized (lock) {
            return linkHandles[linkId("getInteraction", name)];
        }
    }

    /** @return the name of the mass at an index. */
    public String getMatNameAt(int i) {
        synchronized (lock) {
            return mats.name(massAt("getMatNameAt", i));
        }
    }

    /** @return the name of the interaction at an index. */
    public String getLinkNameAt(int i) {
        synchronized (lock) {
            return links.name(linkAt("getLinkNameAt", i));
        }
    }

    /** @return the module type of the mass at an index, for example "Mass3D". */
    public String getMatTypeAt(int i) {
        synchronized (lock) {
            return engine.massKind(massAt("getMatTypeAt", i)).label();
        }
    }

    /** @return the module type of the interaction at an index, for example "SpringDamper3D". */
    public String getLinkTypeAt(int i) {
        synchronized (lock) {
            return engine.linkKind(linkAt("getLinkTypeAt", i)).label();
        }
    }

    /** @return the names of the two masses of an interaction (the same name twice for a plane contact). */
    public String[] getLinkMatNames(String name) {
        synchronized (lock) {
            int id = linkId("getLinkMatNames", name);
            return new String[] {mats.name(engine.linkMassA(id)), mats.name(engine.linkMassB(id))};
        }
    }

    int massId(String op, String name) {
        int id = mats.id(name);
        if (id < 0) {
            throw new IllegalArgumentException(op + "(\"" + name + "\"): no mass with this name");
        }
        return id;
    }

    int linkId(String op, String name) {
        int id = links.id(name);
        if (id < 0) {
            throw new IllegalArgumentException(op + "(\"" + name + "\"): no interaction with this name");
        }
        return id;
    }

    private int massAt(String op, int i) {
        int id = mats.idAt(i);
        if (id < 0) {
            throw new IllegalArgumentException(op + "(" + i + "): mass index out of range 0.." + (mats.size() - 1));
        }
        return id;
    }

    private int linkAt(String op, int i) {
        int id = links.idAt(i);
        if (id < 0) {
            throw new IllegalArgumentException(op + "(" + i + "): interaction index out of range 0.."
                    + (links.size() - 1));
        }
        return id;
    }

    // =================================================================== mass state

    /** @return a copy of the position of a mass. */
    public Vect3D getMatPosition(String name) {
        synchronized (lock) {
            return position(massId("getMatPosition", name), new Vect3D());
        }
    }

    /** Writes the position of a mass into {@code out} (no allocation) and returns it. */
    public Vect3D getMatPosition(String name, Vect3D out) {
        synchronized (lock) {
            return position(massId("getMatPosition", name), out);
        }
    }

    /** @return the position of a mass as a Processing {@code PVector} (float precision). */
    public PVector getMatPVector(String name) {
        return getMatPosition(name).toPVector();
    }

    /** @return the position of the mass at an index. */
    public Vect3D getMatPosAt(int i) {
        synchronized (lock) {
            return position(massAt("getMatPosAt", i), new Vect3D());
        }
    }

    /** @return the velocity of a mass, in units per second (backward difference over the last step). */
    public Vect3D getMatVelocity(String name) {
        synchronized (lock) {
            return velocity(massId("getMatVelocity", name), new Vect3D());
        }
    }

    /** @return the velocity of the mass at an index, in units per second. */
    public Vect3D getMatVelAt(int i) {
        synchronized (lock) {
            return velocity(massAt("getMatVelAt", i), new Vect3D());
        }
    }

    /** @return the force accumulated on a mass by the last interaction phase (REAL_UNITS: N). */
    public Vect3D getMatForce(String name) {
        synchronized (lock) {
            return force(massId("getMatForce", name), new Vect3D());
        }
    }

    /** @return the force on the mass at an index. */
    public Vect3D getMatFrcAt(int i) {
        synchronized (lock) {
            return force(massAt("getMatFrcAt", i), new Vect3D());
        }
    }

    /** @return the force on a mass as a Processing {@code PVector}. */
    public PVector getMatForcePVector(String name) {
        return getMatForce(name).toPVector();
    }

    /** Moves a mass to a position with zero velocity. */
    public void setMatPosition(String name, Vect3D pos) {
        Check.vector("setMatPosition", name, "pos", pos);
        synchronized (lock) {
            int id = massId("setMatPosition", name);
            engine.setPosition(id, pos.x, pos.y, pos.z);
        }
    }

    /** Moves the mass at an index to a position with zero velocity. */
    public void setMatPosAt(int i, Vect3D pos) {
        synchronized (lock) {
            setMatPosition(mats.name(massAt("setMatPosAt", i)), pos);
        }
    }

    /** Sets the velocity of a mass, in units per second, keeping its position. */
    public void setMatVelocity(String name, Vect3D vel) {
        Check.vector("setMatVelocity", name, "vel", vel);
        synchronized (lock) {
            int id = massId("setMatVelocity", name);
            requireInertial("setMatVelocity", id);
            engine.position(id, tmp);
            engine.setState(id, tmp[0], tmp[1], tmp[2], tmp[0] - units.velocityIn(vel.x),
                    tmp[1] - units.velocityIn(vel.y), tmp[2] - units.velocityIn(vel.z));
        }
    }

    /** Adds a force to a mass for the next step only (REAL_UNITS: N). */
    public void triggerForceImpulse(String name, double fx, double fy, double fz) {
        Check.finite("triggerForceImpulse", name, "fx", fx);
        Check.finite("triggerForceImpulse", name, "fy", fy);
        Check.finite("triggerForceImpulse", name, "fz", fz);
        synchronized (lock) {
            engine.addForce(massId("triggerForceImpulse", name), units.forceIn(fx), units.forceIn(fy),
                    units.forceIn(fz));
        }
    }

    /** Adds a force to the mass at an index for the next step only. */
    public void triggerForceImpulse(int i, double fx, double fy, double fz) {
        synchronized (lock) {
            triggerForceImpulse(mats.name(massAt("triggerForceImpulse", i)), fx, fy, fz);
        }
    }

    Vect3D position(int id, Vect3D out) {
        synchronized (lock) {
            engine.position(id, tmp);
            return out.set(tmp[0], tmp[1], tmp[2]);
        }
    }

    Vect3D velocity(int id, Vect3D out) {
        synchronized (lock) {
            engine.displacement(id, tmp);
            return out.set(units.velocityOut(tmp[0]), units.velocityOut(tmp[1]), units.velocityOut(tmp[2]));
        }
    }

    Vect3D force(int id, Vect3D out) {
        synchronized (lock) {
            engine.force(id, tmp);
            return out.set(units.forceOut(tmp[0]), units.forceOut(tmp[1]), units.forceOut(tmp[2]));
        }
    }

    // =================================================================== mass parameters

    /** @return the inertia of a mass (REAL_UNITS: kg). */
    public double getMatMass(String name) {
        synchronized (lock) {
            int id = massId("getMatMass", name);
            requireInertial("getMatMass", id);
            return engine.mass(id);
        }
    }

    /** Sets the inertia of a mass, finite and &gt; 0. */
    public void setMatMass(String name, double mass) {
        synchronized (lock) {
            setMassOf("setMatMass", massId("setMatMass", name), mass);
        }
    }

    /** Sets the inertia of the mass at an index. */
    public void setMatMassAt(int i, double mass) {
        synchronized (lock) {
            setMassOf("setMatMassAt", massAt("setMatMassAt", i), mass);
        }
    }

    /** @return the inertia of the mass at an index. */
    public double getMatMassAt(int i) {
        synchronized (lock) {
            return getMatMass(mats.name(massAt("getMatMassAt", i)));
        }
    }

    /** Sets the internal stiffness of an oscillator (REAL_UNITS: N/m); its coefficients update at once. */
    public void setMatStiffness(String name, double K) {
        Check.finite("setMatStiffness", name, "K", K);
        synchronized (lock) {
            setOscOf("setMatStiffness", massId("setMatStiffness", name), K, Double.NaN);
        }
    }

    /** Sets the internal stiffness of the oscillator at an index. */
    public void setMatStiffnessAt(int i, double K) {
        Check.finite("setMatStiffnessAt", String.valueOf(i), "K", K);
        synchronized (lock) {
            setOscOf("setMatStiffnessAt", massAt("setMatStiffnessAt", i), K, Double.NaN);
        }
    }

    /** Sets the internal damping of an oscillator (REAL_UNITS: N·s/m). */
    public void setMatDamping(String name, double Z) {
        Check.finite("setMatDamping", name, "Z", Z);
        synchronized (lock) {
            setOscOf("setMatDamping", massId("setMatDamping", name), Double.NaN, Z);
        }
    }

    /** Sets the internal damping of the oscillator at an index. */
    public void setMatDampingAt(int i, double Z) {
        Check.finite("setMatDampingAt", String.valueOf(i), "Z", Z);
        synchronized (lock) {
            setOscOf("setMatDampingAt", massAt("setMatDampingAt", i), Double.NaN, Z);
        }
    }

    /** @return the internal stiffness of the oscillator at an index (REAL_UNITS: N/m). */
    public double getMatStiffnessAt(int i) {
        synchronized (lock) {
            return getMatStiffness(mats.name(massAt("getMatStiffnessAt", i)));
        }
    }

    /** @return the internal damping of the oscillator at an index (REAL_UNITS: N·s/m). */
    public double getMatDampingAt(int i) {
        synchronized (lock) {
            return getMatDamping(mats.name(massAt("getMatDampingAt", i)));
        }
    }

    /** @return the internal stiffness of an oscillator. */
    public double getMatStiffness(String name) {
        synchronized (lock) {
            int id = massId("getMatStiffness", name);
            requireOsc("getMatStiffness", id);
            return units.stiffnessOut(engine.oscStiffness(id));
        }
    }

    /** @return the internal damping of an oscillator. */
    public double getMatDamping(String name) {
        synchronized (lock) {
            int id = massId("getMatDamping", name);
            requireOsc("getMatDamping", id);
            return units.dampingOut(engine.oscDamping(id));
        }
    }

    void setMassOf(String op, int id, double mass) {
        synchronized (lock) {
            requireInertial(op, id);
            Check.positive(op, mats.name(id), "mass", mass);
            double old = engine.mass(id);
            engine.setMass(id, mass);
            analyzeAfterChange(() -> engine.setMass(id, old));
        }
    }

    void setOscOf(String op, int id, double K, double Z) {
        synchronized (lock) {
            requireOsc(op, id);
            double oldK = engine.oscStiffness(id), oldZ = engine.oscDamping(id);
            engine.setOscillator(id, Double.isNaN(K) ? oldK : units.stiffnessIn(K),
                    Double.isNaN(Z) ? oldZ : units.dampingIn(Z));
            analyzeAfterChange(() -> engine.setOscillator(id, oldK, oldZ));
        }
    }

    private void requireInertial(String op, int id) {
        if (!engine.massKind(id).isInertial()) {
            throw Check.fail(op, mats.name(id), "a " + engine.massKind(id).label() + " has no mass parameter");
        }
    }

    private void requireOsc(String op, int id) {
        if (!engine.massKind(id).isOscillator()) {
            throw Check.fail(op, mats.name(id), "only Osc3D and Osc1D have stiffness and damping, this is a "
                    + engine.massKind(id).label());
        }
    }

    // =================================================================== interaction state and parameters

    /** @return the current distance between the masses of an interaction (for a plane contact, the gap to the plane). */
    public double getLinkDistance(String name) {
        synchronized (lock) {
            return engine.linkDistance(linkId("getLinkDistance", name));
        }
    }

    /** @return the distance of the interaction at an index. */
    public double getLinkDistanceAt(int i) {
        synchronized (lock) {
            return engine.linkDistance(linkAt("getLinkDistanceAt", i));
        }
    }

    /** @return the elongation of an interaction: its distance minus its length parameter. */
    public double getLinkElongation(String name) {
        synchronized (lock) {
            int id = linkId("getLinkElongation", name);
            return engine.linkDistance(id) - engine.linkLength(id);
        }
    }

    /** @return the elongation of the interaction at an index. */
    public double getLinkElongationAt(int i) {
        synchronized (lock) {
            int id = linkAt("getLinkElongationAt", i);
            return engine.linkDistance(id) - engine.linkLength(id);
        }
    }

    /** @return the stiffness of an interaction (REAL_UNITS: N/m). */
    public double getLinkStiffness(String name) {
        synchronized (lock) {
            return units.stiffnessOut(engine.linkStiffness(linkId("getLinkStiffness", name)));
        }
    }

    /** @return the stiffness of the interaction at an index (REAL_UNITS: N/m). */
    public double getLinkStiffnessAt(int i) {
        synchronized (lock) {
            return units.stiffnessOut(engine.linkStiffness(linkAt("getLinkStiffnessAt", i)));
        }
    }

    /** @return the damping of the interaction at an index (REAL_UNITS: N·s/m). */
    public double getLinkDampingAt(int i) {
        synchronized (lock) {
            return units.dampingOut(engine.linkDamping(linkAt("getLinkDampingAt", i)));
        }
    }

    /** @return the length parameter of the interaction at an index. */
    public double getLinkDRestAt(int i) {
        synchronized (lock) {
            return engine.linkLength(linkAt("getLinkDRestAt", i));
        }
    }

    /** @return the damping of an interaction (REAL_UNITS: N·s/m). */
    public double getLinkDamping(String name) {
        synchronized (lock) {
            return units.dampingOut(engine.linkDamping(linkId("getLinkDamping", name)));
        }
    }

    /** @return the length parameter of an interaction: rest length, threshold, radius, plane offset or limit. */
    public double getLinkDRest(String name) {
        synchronized (lock) {
            return engine.linkLength(linkId("getLinkDRest", name));
        }
    }

    /** Sets the stiffness of an interaction. */
    public void setLinkStiffness(String name, double K) {
        Check.finite("setLinkStiffness", name, "K", K);
        synchronized (lock) {
            setLinkOf("setLinkStiffness", linkId("setLinkStiffness", name), K, Double.NaN, Double.NaN);
        }
    }

    /** Sets the stiffness of the interaction at an index. */
    public void setLinkStiffnessAt(int i, double K) {
        Check.finite("setLinkStiffnessAt", String.valueOf(i), "K", K);
        synchronized (lock) {
            setLinkOf("setLinkStiffnessAt", linkAt("setLinkStiffnessAt", i), K, Double.NaN, Double.NaN);
        }
    }

    /** Sets the damping of an interaction. */
    public void setLinkDamping(String name, double Z) {
        Check.finite("setLinkDamping", name, "Z", Z);
        synchronized (lock) {
            setLinkOf("setLinkDamping", linkId("setLinkDamping", name), Double.NaN, Z, Double.NaN);
        }
    }

    /** Sets the damping of the interaction at an index. */
    public void setLinkDampingAt(int i, double Z) {
        Check.finite("setLinkDampingAt", String.valueOf(i), "Z", Z);
        synchronized (lock) {
            setLinkOf("setLinkDampingAt", linkAt("setLinkDampingAt", i), Double.NaN, Z, Double.NaN);
        }
    }

    /** Sets the length parameter (rest length, threshold, radius, offset or limit) of an interaction. */
    public void setLinkDRest(String name, double d) {
        Check.finite("setLinkDRest", name, "d", d);
        synchronized (lock) {
            setLinkOf("setLinkDRest", linkId("setLinkDRest", name), Double.NaN, Double.NaN, d);
        }
    }

    /** Sets the length parameter of the interaction at an index. */
    public void setLinkDRestAt(int i, double d) {
        Check.finite("setLinkDRestAt", String.valueOf(i), "d", d);
        synchronized (lock) {
            setLinkOf("setLinkDRestAt", linkAt("setLinkDRestAt", i), Double.NaN, Double.NaN, d);
        }
    }

    /** Sets stiffness, damping and length parameter of an interaction together. */
    public void setLinkParams(String name, double K, double Z, double dist) {
        synchronized (lock) {
            int id = linkId("setLinkParams", name);
            Check.finite("setLinkParams", name, "K", K);
            Check.finite("setLinkParams", name, "Z", Z);
            Check.finite("setLinkParams", name, "dist", dist);
            setLinkOf("setLinkParams", id, K, Z, dist);
        }
    }

    /**
     * Sets any of stiffness, damping, length of one link; NaN means "leave unchanged" (public
     * callers reject NaN before calling). Validates everything before changing anything.
     */
    void setLinkOf(String op, int id, double K, double Z, double len) {
        synchronized (lock) {
            LinkKind kind = engine.linkKind(id);
            String n = links.name(id);
            if (!Double.isNaN(K)) {
                if (!kind.hasStiffness()) {
                    throw Check.fail(op, n, "a " + kind.label() + " has no stiffness");
                }
            }
            if (!Double.isNaN(Z)) {
                if (!kind.hasDamping()) {
                    throw Check.fail(op, n, "a " + kind.label() + " has no damping");
                }
            }
            if (!Double.isNaN(len)) {
                if (!kind.hasLength() && kind != LinkKind.ATTRACTOR3D) {
                    throw Check.fail(op, n, "a " + kind.label() + " has no length parameter");
                }
                if (kind == LinkKind.PLANE_CONTACT3D) {
                    Check.finite(op, n, "dist", len);
                } else if (kind == LinkKind.ATTRACTOR3D) {
                    Check.attractorLimit(op, n, len);
                } else {
                    Check.nonNegative(op, n, "dist", len);
                }
            }
            double oldK = engine.linkStiffness(id), oldZ = engine.linkDamping(id), oldL = engine.linkLength(id);
            engine.setLinkParams(id, Double.isNaN(K) ? oldK : units.stiffnessIn(K),
                    Double.isNaN(Z) ? oldZ : units.dampingIn(Z), Double.isNaN(len) ? oldL : len);
            analyzeAfterChange(() -> engine.setLinkParams(id, oldK, oldZ, oldL));
        }
    }

    double linkAuxOut(int id) {
        synchronized (lock) {
            double v = engine.linkAux(id);
            return engine.linkKind(id) == LinkKind.ATTRACTOR3D ? units.forceOut(v) : v;
        }
    }

    void setLinkAuxOf(String op, int id, double v) {
        synchronized (lock) {
            Check.finite(op, links.name(id), "value", v);
            double old = engine.linkAux(id);
            engine.setLinkAux(id, engine.linkKind(id) == LinkKind.ATTRACTOR3D ? units.forceIn(v) : v);
            analyzeAfterChange(() -> engine.setLinkAux(id, old));
        }
    }

    // =================================================================== haptic avatar

    /** Sets the device position that a HapticInput3D (or PosInput3D) follows through its EWMA. */
    public void setHapticPosition(String name, Vect3D pos) {
        Check.vector("setHapticPosition", name, "pos", pos);
        synchronized (lock) {
            int id = massId("setHapticPosition", name);
            requireInput("setHapticPosition", id);
            engine.setInputTarget(id, pos.x, pos.y, pos.z);
        }
    }

    /**
     * Returns the force accumulated on a haptic avatar since the last call, summed over every step
     * in between (REAL_UNITS: N), and resets the accumulator.
     */
    public Vect3D getHapticForce(String name) {
        synchronized (lock) {
            int id = massId("getHapticForce", name);
            requireInput("getHapticForce", id);
            engine.takeForce(id, tmp);
            if (engine.massKind(id) == MassKind.POS_INPUT3D) {
                return new Vect3D();
            }
            return new Vect3D(units.forceOut(tmp[0]), units.forceOut(tmp[1]), units.forceOut(tmp[2]));
        }
    }

    private void requireInput(String op, int id) {
        if (!engine.massKind(id).isInput()) {
            throw Check.fail(op, mats.name(id), "not an input module, this is a " + engine.massKind(id).label());
        }
    }

    // =================================================================== topology

    /** Removes an interaction. */
    public void removeLink(String name) {
        synchronized (lock) {
            removeLinkId(linkId("removeLink", name));
        }
    }

    /** Removes the interaction at an index. */
    public void removeLink(int i) {
        synchronized (lock) {
            removeLinkId(linkAt("removeLink", i));
        }
    }

    private void removeLinkId(int id) {
        engine.removeLink(id);
        links.remove(id);
        linkSubsets.forget(id);
        linkHandles[id].invalidate();
    }

    /** Removes a mass and every interaction connected to it. */
    public void removeMatAndConnectedLinks(String name) {
        synchronized (lock) {
            removeMassId(massId("removeMatAndConnectedLinks", name));
        }
    }

    /** Removes the mass at an index and every interaction connected to it. */
    public void removeMatAndConnectedLinks(int i) {
        synchronized (lock) {
            removeMassId(massAt("removeMatAndConnectedLinks", i));
        }
    }

    private void removeMassId(int id) {
        for (int l : links.ids()) {
            if (engine.linkMassA(l) == id || engine.linkMassB(l) == id) {
                removeLinkId(l);
            }
        }
        engine.removeMass(id);
        mats.remove(id);
        matSubsets.forget(id);
        for (String g : contactGroups.keySet()) {
            syncGroup(g);
        }
        massHandles[id].invalidate();
    }

    /**
     * Turns a mass into a fixed point (Ground3D) at its current position. Its interactions stay
     * attached and its name now designates the fixed point.
     *
     * @return the handle of the new fixed point
     */
    public Ground3D changeToFixedPoint(String name) {
        synchronized (lock) {
            int id = massId("changeToFixedPoint", name);
            engine.makeFixed(id);
            massHandles[id].invalidate();
            return (Ground3D) registerMass(id, MassKind.GROUND3D);
        }
    }

    /** Removes every mass, interaction and subset; names become free again. */
    public void clearModel() {
        synchronized (lock) {
            for (int id : mats.ids()) {
                massHandles[id].invalidate();
            }
            for (int id : links.ids()) {
                linkHandles[id].invalidate();
            }
            engine.clear();
            mats.clear();
            links.clear();
            matSubsets.clear();
            linkSubsets.clear();
            contactGroups.clear();
        }
    }

    // =================================================================== subsets

    /** Creates an empty named group of masses, for grouped parameter changes. */
    public void createMatSubset(String subset) {
        Check.name("createMatSubset", subset);
        synchronized (lock) {
            if (linkSubsets.exists(subset) || !matSubsets.create(subset)) {
                throw Check.fail("createMatSubset", subset, "a mass subset with this name already exists");
            }
        }
    }

    /** Creates an empty named group of interactions. */
    public void createLinkSubset(String subset) {
        Check.name("createLinkSubset", subset);
        synchronized (lock) {
            if (matSubsets.exists(subset) || !linkSubsets.create(subset)) {
                throw Check.fail("createLinkSubset", subset, "a link subset with this name already exists");
            }
        }
    }

    /** Adds a mass to a mass subset. */
    public void addMatToSubset(String mass, String subset) {
        synchronized (lock) {
            int id = massId("addMatToSubset", mass);
            matSubsets.add(requireSubset(matSubsets, "addMatToSubset", subset), id);
            syncGroup(subset);
        }
    }

    /** Adds the mass at an index to a mass subset. */
    public void addMatToSubset(int i, String subset) {
        synchronized (lock) {
            addMatToSubset(mats.name(massAt("addMatToSubset", i)), subset);
        }
    }

    /** Adds an interaction to a link subset. */
    public void addLinkToSubset(String link, String subset) {
        synchronized (lock) {
            int id = linkId("addLinkToSubset", link);
            linkSubsets.add(requireSubset(linkSubsets, "addLinkToSubset", subset), id);
        }
    }

    /** Adds the interaction at an index to a link subset. */
    public void addLinkToSubset(int i, String subset) {
        synchronized (lock) {
            addLinkToSubset(links.name(linkAt("addLinkToSubset", i)), subset);
        }
    }

    /** Removes a mass from a mass subset. */
    public void removeMatFromSubset(String mass, String subset) {
        synchronized (lock) {
            matSubsets.remove(requireSubset(matSubsets, "removeMatFromSubset", subset),
                    massId("removeMatFromSubset", mass));
            syncGroup(subset);
        }
    }

    /** Removes an interaction from a link subset. */
    public void removeLinkFromSubset(String link, String subset) {
        synchronized (lock) {
            linkSubsets.remove(requireSubset(linkSubsets, "removeLinkFromSubset", subset),
                    linkId("removeLinkFromSubset", link));
        }
    }

    /** @return the names of the members of a mass or link subset, in the order they were added. */
    public String[] getSubsetMembers(String subset) {
        synchronized (lock) {
            if (matSubsets.exists(subset)) {
                return matSubsets.members(subset).stream().map(mats::name).toArray(String[]::new);
            }
            return linkSubsets.members(requireSubset(linkSubsets, "getSubsetMembers", subset)).stream()
                    .map(links::name).toArray(String[]::new);
        }
    }

    /** Sets the inertia of every mass in a mass subset. */
    public void changeMassParamOfSubset(double mass, String subset) {
        changeParamOfSubset(mass, subset, "mass");
    }

    /** Sets the stiffness of every member of a subset: links of a link subset, oscillators of a mass subset. */
    public void changeStiffnessParamOfSubset(double K, String subset) {
        changeParamOfSubset(K, subset, "stiffness");
    }

    /** Sets the damping of every member of a subset: links of a link subset, oscillators of a mass subset. */
    public void changeDampingParamOfSubset(double Z, String subset) {
        changeParamOfSubset(Z, subset, "damping");
    }

    /** Sets the length parameter (rest length, threshold, radius) of every interaction in a link subset. */
    public void changeDistParamOfSubset(double d, String subset) {
        changeParamOfSubset(d, subset, "dist");
    }

    /**
     * Sets one parameter on every member of a subset. {@code param} is "mass", "stiffness",
     * "damping" or "dist". Every member is checked before any is changed, so an error leaves the
     * model unchanged.
     */
    public void changeParamOfSubset(double value, String subset, String param) {
        String op = "changeParamOfSubset";
        synchronized (lock) {
            boolean isMat = matSubsets.exists(subset);
            if (!isMat) {
                requireSubset(linkSubsets, op, subset);
            }
            if (!("mass".equals(param) || "stiffness".equals(param) || "damping".equals(param)
                    || "dist".equals(param))) {
                throw Check.fail(op, subset, "param must be \"mass\", \"stiffness\", \"damping\" or \"dist\", got \""
                        + param + "\"");
            }
            Check.finite(op, subset, param, value);
            Set<Integer> members = isMat ? matSubsets.members(subset) : linkSubsets.members(subset);
            for (int id : members) {
                checkSubsetMember(op, isMat, id, param, value);
            }
            java.util.List<Runnable> undo = new java.util.ArrayList<>();
            deferAnalysis++;
            try {
                for (int id : members) {
                    undo.add(snapshot(isMat, id));
                    applySubsetParam(isMat, id, param, value);
                }
            } finally {
                deferAnalysis--;
            }
            analyzeAfterChange(() -> undo.forEach(Runnable::run));
        }
    }

    private void checkSubsetMember(String op, boolean isMat, int id, String param, double value) {
        if (isMat) {
            MassKind k = engine.massKind(id);
            boolean ok = "mass".equals(param) ? k.isInertial()
                    : ("stiffness".equals(param) || "damping".equals(param)) && k.isOscillator();
            if (!ok) {
                throw Check.fail(op, mats.name(id), "a " + k.label() + " has no " + param + " parameter");
            }
            if ("mass".equals(param)) {
                Check.positive(op, mats.name(id), "mass", value);
            }
        } else {
            LinkKind k = engine.linkKind(id);
            boolean ok = "stiffness".equals(param) ? k.hasStiffness()
                    : "damping".equals(param) ? k.hasDamping()
                    : "dist".equals(param) && (k.hasLength() || k == LinkKind.ATTRACTOR3D);
            if (!ok) {
                throw Check.fail(op, links.name(id), "a " + k.label() + " has no " + param + " parameter");
            }
            if ("dist".equals(param) && k == LinkKind.ATTRACTOR3D) {
                Check.attractorLimit(op, links.name(id), value);
            } else if ("dist".equals(param) && k != LinkKind.PLANE_CONTACT3D) {
                Check.nonNegative(op, links.name(id), "dist", value);
            }
        }
    }

    private void applySubsetParam(boolean isMat, int id, String param, double value) {
        if (isMat) {
            if ("mass".equals(param)) {
                engine.setMass(id, value);
            } else {
                setOscOf("changeParamOfSubset", id, "stiffness".equals(param) ? value : Double.NaN,
                        "damping".equals(param) ? value : Double.NaN);
            }
        } else {
            setLinkOf("changeParamOfSubset", id, "stiffness".equals(param) ? value : Double.NaN,
                    "damping".equals(param) ? value : Double.NaN, "dist".equals(param) ? value : Double.NaN);
        }
    }

    private Runnable snapshot(boolean isMat, int id) {
        if (isMat) {
            double m = engine.mass(id);
            if (engine.massKind(id).isOscillator()) {
                double k = engine.oscStiffness(id), z = engine.oscDamping(id);
                return () -> {
                    engine.setMass(id, m);
                    engine.setOscillator(id, k, z);
                };
            }
            return () -> engine.setMass(id, m);
        }
        double k = engine.linkStiffness(id), z = engine.linkDamping(id), l = engine.linkLength(id);
        return () -> engine.setLinkParams(id, k, z, l);
    }

    /** @return the value of a parameter ("mass", "stiffness", "damping", "dist") for the first member of a subset. */
    public double getParamValueOfSubset(String subset, String param) {
        synchronized (lock) {
            boolean isMat = matSubsets.exists(subset);
            Set<Integer> members = isMat ? matSubsets.members(subset)
                    : linkSubsets.members(requireSubset(linkSubsets, "getParamValueOfSubset", subset));
            if (members.isEmpty()) {
                throw Check.fail("getParamValueOfSubset", subset, "the subset is empty");
            }
            int id = members.iterator().next();
            checkSubsetMember("getParamValueOfSubset", isMat, id, param, 1.0);
            if (isMat) {
                return "mass".equals(param) ? engine.mass(id)
                        : "stiffness".equals(param) ? units.stiffnessOut(engine.oscStiffness(id))
                        : units.dampingOut(engine.oscDamping(id));
            }
            return "stiffness".equals(param) ? units.stiffnessOut(engine.linkStiffness(id))
                    : "damping".equals(param) ? units.dampingOut(engine.linkDamping(id)) : engine.linkLength(id);
        }
    }

    /** @return the mean position of the masses of a mass subset. */
    public Vect3D getBarycenterOfSubset(String subset) {
        synchronized (lock) {
            Set<Integer> members = matSubsets.members(requireSubset(matSubsets, "getBarycenterOfSubset", subset));
            if (members.isEmpty()) {
                throw Check.fail("getBarycenterOfSubset", subset, "the subset is empty");
            }
            Vect3D sum = new Vect3D();
            for (int id : members) {
                engine.position(id, tmp);
                sum.x += tmp[0];
                sum.y += tmp[1];
                sum.z += tmp[2];
            }
            return sum.div(members.size());
        }
    }

    private static String requireSubset(Subsets s, String op, String subset) {
        if (subset == null || !s.exists(subset)) {
            throw Check.fail(op, String.valueOf(subset), "no such subset");
        }
        return subset;
    }

    // =================================================================== contact groups

    /**
     * Makes every pair of masses of a mass subset interact like a {@link Contact3D} with the given
     * threshold, stiffness and damping, without N² explicit links: a broad phase (a neighbour list with a
     * skin distance, built on a hashed grid) finds the close pairs. The forces are exactly those of
     * explicit Contact3D links added for every pair (i, j), i before j in subset order. The group follows
     * the subset: masses added to or removed from it later join or leave the group.
     *
     * @param subset an existing mass subset
     * @param threshold contact distance, &gt; 0 (typically the sum of two radii)
     * @param K contact stiffness (REAL_UNITS: N/m)
     * @param Z contact damping (REAL_UNITS: N·s/m)
     */
    public void addContactGroup(String subset, double threshold, double K, double Z) {
        String op = "addContactGroup";
        Check.positive(op, subset, "threshold", threshold);
        Check.finite(op, subset, "K", K);
        Check.finite(op, subset, "Z", Z);
        synchronized (lock) {
            requireSubset(matSubsets, op, subset);
            if (contactGroups.containsKey(subset)) {
                throw Check.fail(op, subset, "this subset already has a contact group");
            }
            int gid = engine.addContactGroup(memberIds(subset), threshold, units.stiffnessIn(K), units.dampingIn(Z));
            contactGroups.put(subset, gid);
            analyzeAfterChange(() -> {
                engine.removeContactGroup(gid);
                contactGroups.remove(subset);
            });
        }
    }

    /** Changes the threshold, stiffness and damping of a subset's contact group. */
    public void setContactGroupParams(String subset, double threshold, double K, double Z) {
        String op = "setContactGroupParams";
        Check.positive(op, subset, "threshold", threshold);
        Check.finite(op, subset, "K", K);
        Check.finite(op, subset, "Z", Z);
        synchronized (lock) {
            int gid = requireGroup(op, subset);
            double[] old = engine.contactGroupParams(gid);
            engine.setContactGroupParams(gid, threshold, units.stiffnessIn(K), units.dampingIn(Z));
            analyzeAfterChange(() -> engine.setContactGroupParams(gid, old[0], old[1], old[2]));
        }
    }

    /** Removes a subset's contact group (the subset itself stays). */
    public void removeContactGroup(String subset) {
        synchronized (lock) {
            engine.removeContactGroup(requireGroup("removeContactGroup", subset));
            contactGroups.remove(subset);
        }
    }

    /** @return true when the mass subset has a contact group. */
    public boolean hasContactGroup(String subset) {
        synchronized (lock) {
            return contactGroups.containsKey(subset);
        }
    }

    private int requireGroup(String op, String subset) {
        Integer gid = contactGroups.get(subset);
        if (gid == null) {
            throw Check.fail(op, String.valueOf(subset), "this subset has no contact group");
        }
        return gid;
    }

    private int[] memberIds(String subset) {
        return matSubsets.members(subset).stream().mapToInt(Integer::intValue).toArray();
    }

    /** Pushes a mass subset's current members to its contact group, if it has one. */
    private void syncGroup(String subset) {
        Integer gid = contactGroups.get(subset);
        if (gid != null) {
            engine.setContactGroupMembers(gid, memberIds(subset));
        }
    }

    /** @return the subset names of the live contact groups, in the engine's compiled order. */
    String[] contactGroupNames() {
        return contactGroups.keySet().toArray(new String[0]);
    }

    // =================================================================== stability and divergence

    /**
     * Sets what the automatic stability analysis does: it runs at {@link #init()} and after every
     * parameter or topology change made after it.
     */
    public void setStabilityPolicy(StabilityPolicy policy) {
        if (policy == null) {
            throw new IllegalArgumentException("setStabilityPolicy: the policy must not be null");
        }
        synchronized (lock) {
            stabilityPolicy = policy;
            lastWarning = null;
        }
    }

    /** @return the current stability policy (WARN by default). */
    public StabilityPolicy getStabilityPolicy() {
        synchronized (lock) {
            return stabilityPolicy;
        }
    }

    /**
     * Sets how many contacts the analysis assumes engaged at once on one mass (12 by default: close
     * packing in 3D; 6 suits a cubic pile, 2 a chain of beads).
     */
    public void setMaxContactsPerMass(int n) {
        if (n < 0) {
            throw new IllegalArgumentException("setMaxContactsPerMass: the count must be >= 0, got " + n);
        }
        synchronized (lock) {
            maxContacts = n;
        }
    }

    /** @return the stability analysis of the model as it is now (see {@link StabilityReport}). */
    public StabilityReport getStabilityReport() {
        synchronized (lock) {
            return StabilityAnalyzer.analyze(engine.plan(), maxContacts);
        }
    }

    /** @return one line describing the model's stability: the margin, or the offending module and its limit. */
    public String describeStability() {
        synchronized (lock) {
            StabilityReport r = getStabilityReport();
            String msg = StabilityMessages.describe(r, engine, mats, links, units, maxContacts, contactGroupNames());
            return msg != null ? msg : String.format(java.util.Locale.ROOT,
                    "Tactus: stable (lambda max = %.4g < 4, every stiffness could grow %.3gx)", r.lambda(),
                    r.headroom());
        }
    }

    private void analyzeAfterChange(Runnable undo) {
        if (!initialized || stabilityPolicy == StabilityPolicy.OFF || deferAnalysis > 0) {
            return;
        }
        StabilityReport r = StabilityAnalyzer.analyze(engine.plan(), maxContacts);
        String msg = StabilityMessages.describe(r, engine, mats, links, units, maxContacts, contactGroupNames());
        if (msg == null) {
            lastWarning = null;
            return;
        }
        if (!r.isStable() && stabilityPolicy == StabilityPolicy.THROW) {
            if (undo != null) {
                undo.run();
            }
            throw new UnstableModelException(msg, r);
        }
        if (!msg.equals(lastWarning)) {
            System.err.println(msg);
            lastWarning = msg;
        }
    }

    /**
     * Registers a listener for divergence events; with a listener, stepping calls no longer throw
     * {@link DivergenceException} but notify it once per divergence. Pass null to go back to exceptions.
     */
    public void setDivergenceListener(DivergenceListener listener) {
        synchronized (lock) {
            divergenceListener = listener;
        }
    }

    /** Sets how often (in steps, &ge; 1, default 64) the running model is checked for divergence. */
    public void setDivergenceCheckInterval(int steps) {
        synchronized (lock) {
            engine.setDivergenceCheckInterval(steps);
        }
    }

    /** Sets the largest coordinate magnitude still considered sane (default 1e12 model length units). */
    public void setDivergenceLimit(double limit) {
        synchronized (lock) {
            engine.guard().setLimit(limit);
        }
    }

    /** @return true when the model has diverged and is frozen. */
    public boolean isDiverged() {
        synchronized (lock) {
            return engine.divergedMass() >= 0;
        }
    }

    /** Lets a diverged model step again; repair its state first (positions, parameters). */
    public void clearDivergence() {
        synchronized (lock) {
            engine.clearDivergence();
            divergenceNotified = false;
        }
    }

    private void checkDivergence() {
        int id = engine.divergedMass();
        if (id < 0) {
            return;
        }
        if (divergenceListener != null && divergenceNotified) {
            return;
        }
        engine.position(id, tmp);
        String name = mats.name(id);
        DivergenceException ex = new DivergenceException(engine.massKind(id).label() + " \"" + name
                + "\" diverged at step " + engine.divergedAt() + ": position (" + tmp[0] + ", " + tmp[1] + ", "
                + tmp[2] + "); the model is frozen until clearDivergence()", name, engine.divergedAt());
        if (divergenceListener != null) {
            divergenceNotified = true;
            divergenceListener.diverged(ex);
            return;
        }
        throw ex;
    }

    // =================================================================== energy

    /** @return the kinetic energy of the model (REAL_UNITS: J), from backward-difference velocities. */
    public double getKineticEnergy() {
        synchronized (lock) {
            return units.forceOut(EnergyMeter.kinetic(engine.plan()));
        }
    }

    /** @return the potential energy stored in engaged springs, oscillators, attractors and gravity (REAL_UNITS: J). */
    public double getPotentialEnergy() {
        synchronized (lock) {
            return units.forceOut(EnergyMeter.potential(engine.plan()));
        }
    }

    /** @return kinetic plus potential energy (REAL_UNITS: J). */
    public double getTotalEnergy() {
        synchronized (lock) {
            StepPlan p = engine.plan();
            return units.forceOut(EnergyMeter.kinetic(p) + EnergyMeter.potential(p));
        }
    }

    // =================================================================== for handles and other rooms

    String massName(int id) {
        synchronized (lock) {
            return mats.name(id);
        }
    }

    String linkName(int id) {
        synchronized (lock) {
            return links.name(id);
        }
    }

    MassKind massKindOf(int id) {
        synchronized (lock) {
            return engine.massKind(id);
        }
    }

    int engineLinkMass(int id, boolean first) {
        synchronized (lock) {
            return first ? engine.linkMassA(id) : engine.linkMassB(id);
        }
    }

    int linkAxisOf(int id) {
        synchronized (lock) {
            return engine.linkAxis(id);
        }
    }

    Mass massHandle(int id) {
        synchronized (lock) {
            return massHandles[id];
        }
    }

    /** Package access to the engine for the facade's handles and tests; callers must hold the lock. */
    Engine engine() {
        return engine;
    }

    UnitScale units() {
        return units;
    }
}
