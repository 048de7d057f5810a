package tactus;

import java.util.concurrent.locks.Lock;
import processing.core.PVector;
import tactus.internal.model.Check;
import tactus.internal.calls.BuildCalls;
import tactus.internal.calls.ModuleCalls;
import tactus.internal.calls.ParamCalls;
import tactus.internal.calls.QueryCalls;
import tactus.internal.calls.SettingsCalls;
import tactus.internal.calls.StateCalls;
import tactus.internal.model.ApiAccess;
import tactus.internal.realtime.ModelLock;
import tactus.internal.realtime.Stepping;
import tactus.internal.ModelCore;

/**
 * A mass-interaction physical model: masses and interactions addressed by name, simulated at a fixed rate with
 * the explicit two-phase scheme of the paper (masses move, then interactions compute forces, with a one-step
 * force delay).
 *
 * <p>Build the model with the {@code add...} methods, call {@link #init()}, then advance it with
 * {@link #draw_physics()} once per frame, or with {@link #computeStep()} / {@link #computeNSteps(int)} from a
 * haptic or audio loop. Parameters are given in the unit system chosen at construction ({@link paramSystem});
 * initial velocities are always in units per second. Bad arguments raise an {@link IllegalArgumentException}
 * that names the element and the value, and leave the model unchanged, except the mistakes that the paper's engine
 * silently ignored (a mass linked to itself, a subset never created, the mass of a ground, ...): the paper's calls
 * forgive those as it did, with one warning per kind, unless the model is strict ({@link #setStrict(boolean)}).
 *
 * <p>Mass names are unique. Interaction names may repeat, as in the paper's sketches (seventy contacts all
 * called "col"): a call that addresses an interaction by a shared name acts on the first one added that is
 * still in the model.
 *
 * <p>All methods are thread-safe: each takes the model's fair lock ({@link #getLock()}) once, except while the
 * model is stepped in realtime ({@link #beginRealtimeStepping()}, which a {@code tactus.audio.PhyUGen} does): then
 * exactly one thread, the owner ({@link #getRealtimeOwner()}), steps the model and takes no lock, and every other
 * thread's changes are queued for it, whatever lock that thread holds (docs/architecture.md, Threads). Long stepping
 * batches ({@link #draw_physics()}, {@link #computeNSteps(int)}) let a waiting thread in between two slices of
 * about 65,000 element updates, so that a parameter change from another thread never waits for a whole batch.
 * This class is the paper's surface and nothing else: each call is documented here and handed in a line to the
 * machinery in {@code tactus.internal} (not API; docs/architecture.md, "Inside tactus").
 */
public class PhysicalModel {
    /** The library version, such as "0.3.0" (the release's, read from the library's resources when it loads). */
    public static final String VERSION = tactus.internal.LibraryVersion.read();

    static {
        ApiAccess.install(new ApiDoors());
    }

    final ModelCore core;
    /** How calls get in and out: the lock, or the owner's gate in realtime mode. */
    final ModelLock gate;
    /** The stepping calls, in both modes. */
    private final Stepping stepping;
    /** The one warning of a model stepped before init(). */
    private final tactus.internal.model.InitNotice initNotice = new tactus.internal.model.InitNotice();
    /** The rest of each call, by concern: once in the model, each hands the work to its room. */
    private final SettingsCalls settings;
    private final BuildCalls build;
    /** The handles of this model's modules, by id (the one place that makes them). */
    private final ModuleHandles handles;
    private final QueryCalls query;
    private final StateCalls state;
    private final ParamCalls param;
    private final ControllerBook controllers = new ControllerBook();

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
        ModuleHandles handles = new ModuleHandles();
        core = new ModelCore(system, simRate, displayRate, handles);
        gate = new ModelLock(core);
        handles.calls = new ModuleCalls(core, gate);
        this.handles = handles;
        core.ramps = controllers;
        stepping = new Stepping(core, gate);
        settings = new SettingsCalls(core, gate);
        build = new BuildCalls(core, gate);
        query = new QueryCalls(core, gate);
        state = new StateCalls(core, gate);
        param = new ParamCalls(core, gate);
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

    /** {@return the library version string} */
    public static String version() {
        return VERSION;
    }

    /**
     * {@return the model's lock; hold it ({@code lock()} ... {@code finally unlock()}) to make several calls
     *     atomic with respect to other threads (while the model is stepped in realtime, with respect to other
     *     editors only: the stepping thread never takes it, and every call made while holding it is queued like any
     *     other, in call order)}
     */
    public Lock getLock() {
        return gate.lock();
    }

    /** {@return the unit system of this model} */
    public paramSystem getParamSystem() {
        return settings.getParamSystem();
    }

    /**
     * Switches the unit system in which every later call takes and returns parameters. The model itself does not
     * change: a spring of 1000 N/m read back in ALGO_UNITS gives its per-step stiffness, 1000 / fs².
     */
    public void setParamSystem(paramSystem system) {
        settings.setParamSystem(system);
    }

    // =================================================================== realtime stepping

    /**
     * Hands the model to one realtime stepping thread (an audio thread). From now on exactly one thread steps the
     * model: the first thread that calls {@link #computeStep()}, {@link #computeNSteps(int)} or
     * {@link #draw_physics()} takes the owner role ({@link #getRealtimeOwner()}). The owner never takes the model's
     * lock, so it never waits for another thread. Every other thread's change is validated, converted and (for
     * parameters) prepared on that thread, queued, and applied by the owner between two steps, in call order, also
     * when that thread holds {@link #getLock()}. A stepping call from another thread while the owner is active does
     * nothing (it prints one message saying so). The role passes on only when the owner ends the mode
     * ({@link #endRealtimeStepping()}), when it has died or has not stepped for 250 ms and another thread needs
     * it, or when another thread claims it ({@link #takeRealtimeStepping()}, which a PhyUGen's audio thread does).
     * {@link tactus.audio.PhyUGen} calls this; see docs/architecture.md (Threads) for the rule and docs/audio.md for
     * which calls are queued and when they apply. Calling it again does nothing.
     */
    public void beginRealtimeStepping() {
        gate.beginRealtime();
    }

    /**
     * Ends realtime stepping: waits for the owner's current stepping call, applies what is still queued, and returns
     * to the locked mode. Called by the owner itself from inside a stepping call (a {@link DivergenceListener}), it
     * never waits for itself: it returns at once, and the mode ends when that stepping call returns (the owner then
     * applies what is queued and gives the role up; {@link #isRealtimeStepping()} turns false as soon as no other
     * thread holds the model's lock).
     */
    public void endRealtimeStepping() {
        gate.endRealtime();
    }

    /**
     * {@return the thread that steps this model in realtime (the owner, see {@link #beginRealtimeStepping()}), or null
     *     when the model is not stepped in realtime or no thread has taken the role yet (or since the last owner
     *     gave it up)}
     */
    public Thread getRealtimeOwner() {
        return gate.owner();
    }

    /**
     * Makes the calling thread the one that steps this realtime-stepped model from now on, even if another thread
     * stepped it before: a {@link tactus.audio.PhyUGen}'s audio thread calls it before it steps, so that a sketch
     * that also calls {@link #draw_physics()} (or started stepping the model before the sound began) cannot keep the
     * audio silent; that sketch's stepping calls then do nothing, with one message. Waits at most for the stepping
     * call in progress on the previous owner. Takes no lock; costs one volatile read when the caller already owns
     * the model.
     *
     * @return true when the calling thread now steps the model; false when the model is not stepped in realtime, or
     *     its realtime mode is ending
     */
    public boolean takeRealtimeStepping() {
        return gate.claim();
    }

    /**
     * Begins a run of calls that the realtime stepping thread makes together, such as one audio sample of a
     * {@link tactus.audio.PhyUGen}: a step, then the reads of its listening points. The calling thread takes the
     * owner role as {@link #computeStep()} would, applies what other threads queued, and enters the model once for
     * the whole run; its calls until {@link #endRealtimeCalls()} (stepping calls, reads, avatar writes) then enter
     * nothing. Other threads' changes are applied when the run begins and by its stepping calls (before they step),
     * never by its reads; another thread cannot end the mode or take the role during a run.
     * Takes no lock and never waits for another thread, except, like {@link #computeStep()}, for one applying
     * queued changes when there is no owner. Keep the run short (one sample): it holds the model as a stepping call
     * does.
     *
     * @return true when the run has begun: call {@link #endRealtimeCalls()} in a {@code finally}; false when the
     *     model is not stepped in realtime, its realtime mode is ending, or another active thread owns it: nothing
     *     was begun, the calls behave as they do without it, and {@link #endRealtimeCalls()} must not be called
     */
    public boolean beginRealtimeCalls() {
        return gate.beginOwnerSection();
    }

    /**
     * Ends a run begun by {@link #beginRealtimeCalls()} that returned true: lets other threads' changes in again (and
     * ends the realtime mode if a call of the run asked to end it). Does nothing on a thread that holds no run.
     */
    public void endRealtimeCalls() {
        gate.endOwnerSection();
    }

    /**
     * {@return the number of queued changes (over the life of the model) that found one of their targets removed
     *     when the stepping thread applied them, for example a {@code setLinkStiffness} queued just before a
     *     {@link DivergenceListener} on the audio thread removed that link: the writes to the removed modules were
     *     skipped (the others applied) and nothing was thrown}
     */
    public long getDroppedCommands() {
        return gate.droppedCommands();
    }

    /** {@return true while the model is stepped in realtime (see {@link #beginRealtimeStepping()})} */
    public boolean isRealtimeStepping() {
        return gate.mode() != null;
    }

    // =================================================================== rates and stepping

    /** {@return the simulation rate, in steps per second} */
    public int getSimRate() {
        return settings.getSimRate();
    }

    /**
     * Changes the simulation rate. In REAL_UNITS every coefficient (links, oscillators, attractors, contact
     * groups, the medium) is re-derived so the model keeps describing the same physical system, and velocities
     * (in units per second) are kept. In ALGO_UNITS coefficients are per step and stay as they are. Under
     * {@link StabilityPolicy#THROW} a rate that makes the model unstable is refused and everything is restored.
     *
     * <p>While a realtime driver holds the rate ({@link #holdSimRate(Object)}: a {@code tactus.audio.PhyUGen}
     * playing the model, which must step at its output's rate), the change is refused with an
     * {@link IllegalStateException} that names the driver and the rates, and the model is left unchanged.
     *
     * @param rate steps per second, &gt; 0
     */
    public void setSimRate(int rate) {
        stepping.setSimRate(rate);
    }

    /**
     * Fixes the simulation rate for the driver that steps the model in realtime and dictates its rate: a
     * {@code tactus.audio.PhyUGen} calls it, since the model must step at its output's rate times its
     * oversampling. Until realtime stepping ends ({@link #endRealtimeStepping()}), {@link #setSimRate(int)}
     * throws an {@link IllegalStateException} whose message ends with {@code holder.toString()} (say who holds
     * the rate and how to change it) and leaves the model unchanged; the driver changes the rate through the
     * returned setter. A later call hands the rate to another driver.
     *
     * @param holder the driver, described in the refusal by its {@code toString()}
     * @return the driver's rate setter, in steps per second (&gt; 0; same checks and effects as setSimRate)
     * @throws IllegalStateException if the model is not stepped in realtime
     */
    public java.util.function.IntConsumer holdSimRate(Object holder) {
        return stepping.holdSimRate(holder);
    }

    /** {@return the display rate, in frames per second} */
    public int getDisplayRate() {
        return settings.getDisplayRate();
    }

    /** Sets the display rate used by {@link #draw_physics()}, in frames per second (&gt; 0). */
    public void setDisplayRate(int rate) {
        settings.setDisplayRate(rate);
    }

    /**
     * Prepares the model for simulation: compiles the scene into its step plan and checks its stability. Call
     * it once after building; from then on every topology change is compiled at once, by the thread making it.
     */
    public void init() {
        settings.init();
    }

    /**
     * Advances the model by one display frame: {@code floor(simRate / displayRate + r)} steps, where the
     * fractional remainder r is carried to the next frame in exact integer arithmetic (frame n runs
     * {@code floor(n·simRate/displayRate) - floor((n-1)·simRate/displayRate)} steps). The paper's engine carried it
     * in floating point, so at rates whose ratio is not exact in {@code float} (1000 Hz and 60 fps: after frames
     * 3, 6, 9, ...) Tactus is one step ahead of it on some frames; at 44100 Hz and 60 fps both run 735 steps.
     *
     * @return the number of steps of this frame
     */
    public int draw_physics() {
        initNotice.check(core.initialized, "draw_physics()");
        return stepping.frame();
    }

    /** Runs one simulation step. */
    public void computeStep() {
        initNotice.check(core.initialized, "computeStep()");
        stepping.step();
    }

    /** Runs {@code n} simulation steps (n &ge; 0). */
    public void computeNSteps(int n) {
        if (n < 0) {
            throw new IllegalArgumentException("computeNSteps: the step count must be >= 0, got " + n);
        }
        initNotice.check(core.initialized, "computeNSteps()");
        stepping.steps(n);
    }

    /**
     * Runs up to {@code n} simulation steps as one stepping call and records, after each step, one position
     * coordinate of each given mass: {@code out[s * masses.length + i]} is coordinate {@code axes[i]} (0 x, 1 y, 2 z;
     * model units) of {@code masses[i]} after step s, the first step being s = 0. This is how a block of audio is
     * computed in one pass ({@link tactus.audio.PhyUGen} uses it): the model is entered once for the whole block, and
     * changes that other threads queued are applied once, before the first step. The steps are the same as
     * {@link #computeNSteps(int)}'s. Allocates nothing once the calling thread has recorded this many masses before.
     *
     * @param n the number of steps, &ge; 0
     * @param masses the masses to read, each a handle of this model
     * @param axes one axis per mass: 0 (x), 1 (y) or 2 (z)
     * @param out at least {@code n * masses.length} values
     * @return the number of steps run: fewer than n when the model diverged, 0 when another thread steps this
     *     realtime-stepped model (see {@link #beginRealtimeStepping()})
     * @throws IllegalArgumentException naming the argument when one is missing, of the wrong length, or names a
     *     mass of another model; IllegalStateException when a mass has left the model; nothing is stepped then
     */
    public int computeNStepsRecording(int n, Mass[] masses, int[] axes, double[] out) {
        String call = "computeNStepsRecording";
        if (n < 0) {
            throw new IllegalArgumentException(call + ": the step count must be >= 0, got " + n);
        }
        if (masses == null || axes == null || out == null) {
            throw new IllegalArgumentException(call + ": give the masses, their axes and the output array (got "
                    + (masses == null ? "no masses" : axes == null ? "no axes" : "no output array") + ")");
        }
        int count = masses.length;
        if (axes.length != count) {
            throw new IllegalArgumentException(call + ": give one axis per mass (" + count + " masses, "
                    + axes.length + " axes)");
        }
        if ((long) n * count > out.length) {
            throw new IllegalArgumentException(call + ": the output array holds " + out.length + " values; " + n
                    + " steps of " + count + " masses need " + (long) n * count);
        }
        int[][] scratch = recordScratch.get();
        if (scratch[0].length < count) {
            scratch = new int[][] {new int[count], new int[count]};
            recordScratch.set(scratch);
        }
        for (int i = 0; i < count; i++) {
            Mass m = masses[i];
            if (m == null || m.handles != handles) {
                throw new IllegalArgumentException(call + ": masses[" + i + "] is " + (m == null ? "null"
                        : "a mass of another model") + "; give handles of this model (getMass(name))");
            }
            if (axes[i] < 0 || axes[i] > 2) {
                throw new IllegalArgumentException(call + ": axes[" + i + "] must be 0 (x), 1 (y) or 2 (z), got "
                        + axes[i]);
            }
            scratch[0][i] = m.id;
            scratch[1][i] = m.stamp;
        }
        initNotice.check(core.initialized, "computeNStepsRecording()");
        return stepping.stepsRecording(n, scratch[0], scratch[1], axes, count, out);
    }

    /** Mass ids and stamps of {@link #computeNStepsRecording}, per calling thread. */
    private final ThreadLocal<int[][]> recordScratch = ThreadLocal.withInitial(() -> new int[][] {new int[4], new int[4]});

    /**
     * Lets large models step on several threads (1, the default, keeps everything on the calling thread). Only
     * models of at least 20,000 elements (masses plus interactions) stepped several steps at a time
     * ({@link #computeNSteps(int)}, {@link #draw_physics()}) use them; results are bit-identical to one thread.
     * Use at most the number of cores left free by the audio and haptic threads. The worker threads stop with
     * {@link #dispose()}.
     *
     * @param threads 1 to 64
     */
    public void setThreads(int threads) {
        settings.setThreads(threads);
    }

    /** {@return the number of threads large models may use} */
    public int getThreads() {
        return settings.getThreads();
    }

    /** {@return the number of steps simulated since the model was created} */
    public long getStepCount() {
        return settings.getStepCount();
    }

    /**
     * {@return what one step computes, in order, one label per computation the compiled plan runs (for example
     *     "free 3D masses", "3D masses with gravity or friction", "fixed points", "springs"): a scene pays only
     *     for the effects it has}
     */
    public String[] getSimulatedEffects() {
        return settings.getSimulatedEffects();
    }

    /**
     * Stops the worker threads of parallel stepping ({@link #setThreads(int)}); the model stays usable and
     * steps on the calling thread. Worker threads also stop by themselves once the model is no longer reachable.
     */
    public void dispose() {
        settings.dispose();
    }

    /**
     * Returns a consistent copy of the model's state, for drawing from a thread that does not step the model. The
     * copy is never torn, and this call never delays an audio or haptic thread. Call it from one thread only (the
     * sketch's animation thread); the returned object stays valid until that thread's next call.
     *
     * <p>The model copies its state only for a reader: until the first call it copies nothing (a model that is never
     * drawn pays nothing). Interactions are copied unless the reader declines them
     * ({@link ModelSnapshot#requestLinks}). What a call returns:
     * <ul>
     *   <li>Locked mode (no realtime stepping): when the lock is free, the current state (this call copies it,
     *       unless the newest copy already shows the current step); when another thread holds the lock, the newest
     *       copy, and that thread publishes a fresh one after the step that ends the current display frame of
     *       simulated time. After {@link #init()} or a topology change that no call has seen yet, this call waits
     *       for the lock (at most one slice of a stepping batch) and copies the new topology.</li>
     *   <li>Realtime mode ({@link #beginRealtimeStepping()}): the newest copy published by the stepping thread, which
     *       publishes at most once per display frame of simulated time ({@link #getDisplayRate()}) while this method
     *       is called, and for a few frames after the last call; a topology change is published before the call
     *       that made it returns. After a pause in reading of more than a few frames, the first call returns the
     *       last copy published (from the start of the pause) and the stepping thread publishes at its next
     *       stepping call, so the next call is fresh.</li>
     * </ul>
     *
     * @return the newest snapshot (empty, with step -1, before {@link #init()})
     */
    public ModelSnapshot getSnapshot() {
        return stepping.snapshot().view;
    }

    // =================================================================== global medium

    /**
     * Sets the gravity magnitude (REAL_UNITS: m/s²). Masses accelerate along minus the gravity direction, so
     * with the default direction (0, 0, 1) they fall toward -z. Mass1D and Osc1D feel its z component, which the
     * paper's engine did not give them: the first time gravity pulls along z in a model with a 1D mass (set here,
     * by {@link #setGravityDirection(Vect3D)}, or by adding a 1D mass), a note says so, once per model.
     */
    public void setGravity(double magnitude) {
        settings.setGravity(magnitude);
    }

    /** {@return the gravity magnitude in model units} */
    public double getGravity() {
        return settings.getGravity();
    }

    /** Sets the gravity direction ("up"); it is normalised. Masses accelerate along its opposite. */
    public void setGravityDirection(Vect3D direction) {
        settings.setGravityDirection(direction);
    }

    /**
     * Sets the gravity direction ("up") from its three components; it is normalised. The same as
     * {@link #setGravityDirection(Vect3D)}, for a program without Processing core on the class path: there javac
     * cannot choose between the one-argument forms, since one of them takes a {@code PVector}.
     */
    public void setGravityDirection(double x, double y, double z) {
        setGravityDirection(new Vect3D(x, y, z));
    }

    /** Sets the gravity direction ("up") from a Processing vector; see {@link #setGravityDirection(Vect3D)}. */
    public void setGravityDirection(PVector direction) {
        if (direction == null) {
            throw Check.fail("setGravityDirection", "gravity", "direction must not be null");
        }
        setGravityDirection(new Vect3D(direction.x, direction.y, direction.z));
    }

    /** {@return a copy of the normalised gravity direction} */
    public Vect3D getGravityDirection() {
        return settings.getGravityDirection();
    }

    /** Sets the air friction applied to every moving mass (REAL_UNITS: N·s/m), &ge; 0 in normal use. */
    public void setFriction(double f) {
        settings.setFriction(f);
    }

    /** {@return the air friction in model units} */
    public double getFriction() {
        return settings.getFriction();
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
        return handles.mass(build.addMass3D(name, mass, initPos, initVel));
    }

    /** Adds a free 3D mass that ignores air friction and gravity: only its interactions move it. */
    public Mass3DSimple addMass3DSimple(String name, double mass, Vect3D initPos, Vect3D initVel) {
        return handles.mass(build.addMass3DSimple(name, mass, initPos, initVel));
    }

    /** Adds a mass that moves in its initial z plane only (see {@link #addMass3D}). */
    public Mass2DPlane addMass2DPlane(String name, double mass, Vect3D initPos, Vect3D initVel) {
        return handles.mass(build.addMass2DPlane(name, mass, initPos, initVel));
    }

    /** Adds a mass that moves along z only (see {@link #addMass3D}). */
    public Mass1D addMass1D(String name, double mass, Vect3D initPos, Vect3D initVel) {
        return handles.mass(build.addMass1D(name, mass, initPos, initVel));
    }

    /** Adds a fixed point in 3D. */
    public Ground3D addGround3D(String name, Vect3D initPos) {
        return handles.mass(build.addGround3D(name, initPos));
    }

    /** Adds a fixed point for 1D models. */
    public Ground1D addGround1D(String name, Vect3D initPos) {
        return handles.mass(build.addGround1D(name, initPos));
    }

    /**
     * Adds a 3D oscillator: a mass tied to its initial position by an internal spring K and damper Z
     * (REAL_UNITS: N/m and N·s/m), also subject to air friction and gravity.
     */
    public Osc3D addOsc3D(String name, double mass, double K, double Z, Vect3D initPos, Vect3D initVel) {
        return handles.mass(build.addOsc3D(name, mass, K, Z, initPos, initVel));
    }

    /** Adds an oscillator that moves along z only (see {@link #addOsc3D}). */
    public Osc1D addOsc1D(String name, double mass, double K, double Z, Vect3D initPos, Vect3D initVel) {
        return handles.mass(build.addOsc1D(name, mass, K, Z, initPos, initVel));
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
        return handles.mass(build.addOsc3DTuned(name, mass, freqHz, t60, initPos, initVel));
    }

    /** Adds a 1D oscillator tuned by its pitch and decay (see {@link #addOsc3DTuned}). */
    public Osc1D addOsc1DTuned(String name, double mass, double freqHz, double t60, Vect3D initPos, Vect3D initVel) {
        return handles.mass(build.addOsc1DTuned(name, mass, freqHz, t60, initPos, initVel));
    }

    /** Retunes an oscillator to ring at exactly {@code freqHz} and decay by 60 dB in {@code t60} seconds. */
    public void tuneOsc(String name, double freqHz, double t60) {
        build.tuneOsc(name, freqHz, t60);
    }

    /** {@return the frequency (Hz) at which an oscillator actually rings in this scheme, friction included} */
    public double getOscFrequency(String name) {
        return build.getOscFrequency(name);
    }

    /** {@return the 60 dB decay time (seconds) of an oscillator in this scheme, friction included} */
    public double getOscT60(String name) {
        return build.getOscT60(name);
    }

    /**
     * Adds the haptic avatar: its position follows the device position through an exponentially weighted
     * moving average of weight 1/smoothing per step, and it accumulates the force the model applies to it until
     * {@link #getHapticForce(String)} reads it.
     *
     * @param smoothing EWMA length in steps, &ge; 1 (1 means no smoothing)
     */
    public HapticInput3D addHapticInput3D(String name, Vect3D initPos, int smoothing) {
        return handles.mass(build.addHapticInput3D(name, initPos, smoothing));
    }

    /** Adds a kinematic position driver that follows its target through an EWMA (weight 1/smoothing). */
    public PosInput3D addPosInput3D(String name, Vect3D initPos, int smoothing) {
        return handles.mass(build.addPosInput3D(name, initPos, smoothing));
    }

    // =================================================================== adding interactions

    /** Adds a spring: force -K (d - dist) along the line between the masses (REAL_UNITS: K in N/m). */
    public Spring3D addSpring3D(String name, double dist, double K, String m1, String m2) {
        return handles.link(build.addSpring3D(name, dist, K, m1, m2));
    }

    /** Adds a spring between two mass handles (see {@link #addSpring3D(String, double, double, String, String)}). */
    public Spring3D addSpring3D(String name, double dist, double K, Mass m1, Mass m2) {
        String[] n = handles.distinct("addSpring3D", name, m1, m2);
        return addSpring3D(name, dist, K, n[0], n[1]);
    }

    /** Adds a damper: force -Z (d(n) - d(n-1)) along the line between the masses (REAL_UNITS: N·s/m). */
    public Damper3D addDamper3D(String name, double Z, String m1, String m2) {
        return handles.link(build.addDamper3D(name, Z, m1, m2));
    }

    /** Adds a damper between two mass handles. */
    public Damper3D addDamper3D(String name, double Z, Mass m1, Mass m2) {
        String[] n = handles.distinct("addDamper3D", name, m1, m2);
        return addDamper3D(name, Z, n[0], n[1]);
    }

    /** Adds a spring and damper in parallel, with rest length {@code dist}. */
    public SpringDamper3D addSpringDamper3D(String name, double dist, double K, double Z, String m1, String m2) {
        return handles.link(build.addSpringDamper3D(name, dist, K, Z, m1, m2));
    }

    /** Adds a spring-damper between two mass handles. */
    public SpringDamper3D addSpringDamper3D(String name, double dist, double K, double Z, Mass m1, Mass m2) {
        String[] n = handles.distinct("addSpringDamper3D", name, m1, m2);
        return addSpringDamper3D(name, dist, K, Z, n[0], n[1]);
    }

    /** Adds a spring-damper that acts along z only, on the signed difference z1 - z2 with rest value {@code dist}. */
    public SpringDamper1D addSpringDamper1D(String name, double dist, double K, double Z, String m1, String m2) {
        return handles.link(build.addSpringDamper1D(name, dist, K, Z, m1, m2));
    }

    /** Adds a 1D spring-damper between two mass handles. */
    public SpringDamper1D addSpringDamper1D(String name, double dist, double K, double Z, Mass m1, Mass m2) {
        String[] n = handles.distinct("addSpringDamper1D", name, m1, m2);
        return addSpringDamper1D(name, dist, K, Z, n[0], n[1]);
    }

    /** Adds a rope: a spring-damper that acts only while the masses are farther apart than {@code dist}. */
    public Rope3D addRope3D(String name, double dist, double K, double Z, String m1, String m2) {
        return handles.link(build.addRope3D(name, dist, K, Z, m1, m2));
    }

    /** Adds a rope between two mass handles. */
    public Rope3D addRope3D(String name, double dist, double K, double Z, Mass m1, Mass m2) {
        String[] n = handles.distinct("addRope3D", name, m1, m2);
        return addRope3D(name, dist, K, Z, n[0], n[1]);
    }

    /** Adds a contact: a spring-damper that acts only while the masses are closer than the threshold {@code dist}. */
    public Contact3D addContact3D(String name, double dist, double K, double Z, String m1, String m2) {
        return handles.link(build.addContact3D(name, dist, K, Z, m1, m2));
    }

    /** Adds a contact between two mass handles. */
    public Contact3D addContact3D(String name, double dist, double K, double Z, Mass m1, Mass m2) {
        String[] n = handles.distinct("addContact3D", name, m1, m2);
        return addContact3D(name, dist, K, Z, n[0], n[1]);
    }

    /** Adds a bubble: keeps m1 within radius {@code dist} of m2 with a spring-damper acting only outside it. */
    public Bubble3D addBubble3D(String name, double dist, double K, double Z, String m1, String m2) {
        return handles.link(build.addBubble3D(name, dist, K, Z, m1, m2));
    }

    /** Adds a bubble between two mass handles. */
    public Bubble3D addBubble3D(String name, double dist, double K, double Z, Mass m1, Mass m2) {
        String[] n = handles.distinct("addBubble3D", name, m1, m2);
        return addBubble3D(name, dist, K, Z, n[0], n[1]);
    }

    /**
     * Adds a one-sided contact between a mass and an axis-aligned plane. The plane is normal to axis
     * {@code orientation} (0 = x, 1 = y, 2 = z) at coordinate {@code pos}; while the mass coordinate q is below
     * {@code pos + l0} it is pushed back with {@code -K t - Z dq}, where {@code t = q - pos - l0}.
     */
    public PlaneContact3D addPlaneContact(String name, double l0, double K, double Z, int orientation,
                                          double pos, String m1) {
        return handles.link(build.addPlaneContact(name, l0, K, Z, orientation, pos, m1));
    }

    /** Adds a plane contact on a mass handle. */
    public PlaneContact3D addPlaneContact(String name, double l0, double K, double Z, int orientation,
                                          double pos, Mass m1) {
        return addPlaneContact(name, l0, K, Z, orientation, pos, handles.nameOf(m1));
    }

    /**
     * Adds an inverse-square attractor: force -attr / d² between the masses while d &gt; dLim (REAL_UNITS: attr
     * in N·m²). A negative factor repels. dLim must be &gt; 0: closer than that the force is not applied, which
     * keeps it bounded by attr / dLim².
     */
    public Attractor3D addAttractor3D(String name, double dLim, double attr, String m1, String m2) {
        return handles.link(build.addAttractor3D(name, dLim, attr, m1, m2));
    }

    /** Adds an attractor between two mass handles. */
    public Attractor3D addAttractor3D(String name, double dLim, double attr, Mass m1, Mass m2) {
        String[] n = handles.distinct("addAttractor3D", name, m1, m2);
        return addAttractor3D(name, dLim, attr, n[0], n[1]);
    }

    // ---- Faust mi.lib's nonlinear interactions (docs/modules.md)

    /**
     * Adds a nonlinear interaction of any type by its type, what model loaders use: {@code extra} holds the
     * parameters of {@link linkModuleType#extraParameterNames()} in that order, in the model's units; a type
     * without stiffness or length ignores K or dist.
     *
     * @throws IllegalArgumentException when the type is not a nonlinear one or {@code extra} has the wrong length
     */
    public Interaction addInteraction(linkModuleType type, String name, double dist, double K, double Z,
                                      double[] extra, String m1, String m2) {
        return handles.link(build.addInteraction(type, name, dist, K, Z, extra, m1, m2));
    }

    /**
     * Adds a spring-damper with a quadratic term, along the line between the masses (mi.lib's nlSpringDamper2): F = K
     * e + Q sgn(e) e^2 + Z v, e = d - dist; Q in N/m^2 (REAL_UNITS).
     */
    public QuadraticSpringDamper3D addQuadraticSpringDamper3D(String name, double dist, double K, double Z, double Q,
            String m1, String m2) {
        return handles.link(build.addQuadraticSpringDamper3D(name, dist, K, Z, Q, m1, m2));
    }

    /**
     * Adds a spring-damper with a quadratic term, along the line between the masses (mi.lib's nlSpringDamper2): F = K
     * e + Q sgn(e) e^2 + Z v, e = d - dist; Q in N/m^2 (REAL_UNITS).
     */
    public QuadraticSpringDamper3D addQuadraticSpringDamper3D(String name, double dist, double K, double Z, double Q,
            Mass m1, Mass m2) {
        String[] n = handles.distinct("addQuadraticSpringDamper3D", name, m1, m2);
        return addQuadraticSpringDamper3D(name, dist, K, Z, Q, n[0], n[1]);
    }

    /**
     * Adds a spring-damper with a quadratic term along z (mi.lib's nlSpringDamper2): F = K e + Q sgn(e) e^2 + Z v, e =
     * z1 - z2 - dist; Q in N/m^2 (REAL_UNITS).
     */
    public QuadraticSpringDamper1D addQuadraticSpringDamper1D(String name, double dist, double K, double Z, double Q,
            String m1, String m2) {
        return handles.link(build.addQuadraticSpringDamper1D(name, dist, K, Z, Q, m1, m2));
    }

    /**
     * Adds a spring-damper with a quadratic term along z (mi.lib's nlSpringDamper2): F = K e + Q sgn(e) e^2 + Z v, e =
     * z1 - z2 - dist; Q in N/m^2 (REAL_UNITS).
     */
    public QuadraticSpringDamper1D addQuadraticSpringDamper1D(String name, double dist, double K, double Z, double Q,
            Mass m1, Mass m2) {
        String[] n = handles.distinct("addQuadraticSpringDamper1D", name, m1, m2);
        return addQuadraticSpringDamper1D(name, dist, K, Z, Q, n[0], n[1]);
    }

    /**
     * Adds a spring-damper with a cubic term, along the line between the masses (mi.lib's nlSpringDamper3): F = K e +
     * Q e^3 + Z v, e = d - dist; Q in N/m^3 (REAL_UNITS).
     */
    public CubicSpringDamper3D addCubicSpringDamper3D(String name, double dist, double K, double Z, double Q, String m1,
            String m2) {
        return handles.link(build.addCubicSpringDamper3D(name, dist, K, Z, Q, m1, m2));
    }

    /**
     * Adds a spring-damper with a cubic term, along the line between the masses (mi.lib's nlSpringDamper3): F = K e +
     * Q e^3 + Z v, e = d - dist; Q in N/m^3 (REAL_UNITS).
     */
    public CubicSpringDamper3D addCubicSpringDamper3D(String name, double dist, double K, double Z, double Q, Mass m1,
            Mass m2) {
        String[] n = handles.distinct("addCubicSpringDamper3D", name, m1, m2);
        return addCubicSpringDamper3D(name, dist, K, Z, Q, n[0], n[1]);
    }

    /**
     * Adds a spring-damper with a cubic term along z (mi.lib's nlSpringDamper3): F = K e + Q e^3 + Z v, e = z1 - z2 -
     * dist; Q in N/m^3 (REAL_UNITS).
     */
    public CubicSpringDamper1D addCubicSpringDamper1D(String name, double dist, double K, double Z, double Q, String m1,
            String m2) {
        return handles.link(build.addCubicSpringDamper1D(name, dist, K, Z, Q, m1, m2));
    }

    /**
     * Adds a spring-damper with a cubic term along z (mi.lib's nlSpringDamper3): F = K e + Q e^3 + Z v, e = z1 - z2 -
     * dist; Q in N/m^3 (REAL_UNITS).
     */
    public CubicSpringDamper1D addCubicSpringDamper1D(String name, double dist, double K, double Z, double Q, Mass m1,
            Mass m2) {
        String[] n = handles.distinct("addCubicSpringDamper1D", name, m1, m2);
        return addCubicSpringDamper1D(name, dist, K, Z, Q, n[0], n[1]);
    }

    /**
     * Adds a cubic spring-damper bounded by the stiffness Kmax, along the line between the masses (mi.lib's
     * nlSpringDamperClipped with s = K, c = C, k = Kmax); C in N/m^3, Kmax in N/m (REAL_UNITS).
     */
    public ClippedSpringDamper3D addClippedSpringDamper3D(String name, double dist, double K, double Z, double C,
            double Kmax, String m1, String m2) {
        return handles.link(build.addClippedSpringDamper3D(name, dist, K, Z, C, Kmax, m1, m2));
    }

    /**
     * Adds a cubic spring-damper bounded by the stiffness Kmax, along the line between the masses (mi.lib's
     * nlSpringDamperClipped with s = K, c = C, k = Kmax); C in N/m^3, Kmax in N/m (REAL_UNITS).
     */
    public ClippedSpringDamper3D addClippedSpringDamper3D(String name, double dist, double K, double Z, double C,
            double Kmax, Mass m1, Mass m2) {
        String[] n = handles.distinct("addClippedSpringDamper3D", name, m1, m2);
        return addClippedSpringDamper3D(name, dist, K, Z, C, Kmax, n[0], n[1]);
    }

    /**
     * Adds a cubic spring-damper bounded by the stiffness Kmax, along z (mi.lib's nlSpringDamperClipped with s = K, c
     * = C, k = Kmax); C in N/m^3, Kmax in N/m (REAL_UNITS).
     */
    public ClippedSpringDamper1D addClippedSpringDamper1D(String name, double dist, double K, double Z, double C,
            double Kmax, String m1, String m2) {
        return handles.link(build.addClippedSpringDamper1D(name, dist, K, Z, C, Kmax, m1, m2));
    }

    /**
     * Adds a cubic spring-damper bounded by the stiffness Kmax, along z (mi.lib's nlSpringDamperClipped with s = K, c
     * = C, k = Kmax); C in N/m^3, Kmax in N/m (REAL_UNITS).
     */
    public ClippedSpringDamper1D addClippedSpringDamper1D(String name, double dist, double K, double Z, double C,
            double Kmax, Mass m1, Mass m2) {
        String[] n = handles.distinct("addClippedSpringDamper1D", name, m1, m2);
        return addClippedSpringDamper1D(name, dist, K, Z, C, Kmax, n[0], n[1]);
    }

    /**
     * Adds a pluck along the line between the masses (mi.lib's nlPluck): it pushes back on the elongation d - dist and
     * lets go once |d - dist| reaches scale (length units, > 0).
     */
    public Pluck3D addPluck3D(String name, double dist, double K, double Z, double scale, String m1, String m2) {
        return handles.link(build.addPluck3D(name, dist, K, Z, scale, m1, m2));
    }

    /**
     * Adds a pluck along the line between the masses (mi.lib's nlPluck): it pushes back on the elongation d - dist and
     * lets go once |d - dist| reaches scale (length units, > 0).
     */
    public Pluck3D addPluck3D(String name, double dist, double K, double Z, double scale, Mass m1, Mass m2) {
        String[] n = handles.distinct("addPluck3D", name, m1, m2);
        return addPluck3D(name, dist, K, Z, scale, n[0], n[1]);
    }

    /**
     * Adds a pluck along z (mi.lib's nlPluck): it pushes back on z1 - z2 - dist and lets go once that reaches scale
     * (length units, > 0).
     */
    public Pluck1D addPluck1D(String name, double dist, double K, double Z, double scale, String m1, String m2) {
        return handles.link(build.addPluck1D(name, dist, K, Z, scale, m1, m2));
    }

    /**
     * Adds a pluck along z (mi.lib's nlPluck): it pushes back on z1 - z2 - dist and lets go once that reaches scale
     * (length units, > 0).
     */
    public Pluck1D addPluck1D(String name, double dist, double K, double Z, double scale, Mass m1, Mass m2) {
        String[] n = handles.distinct("addPluck1D", name, m1, m2);
        return addPluck1D(name, dist, K, Z, scale, n[0], n[1]);
    }

    /**
     * Adds a bowing friction against the relative velocity of the masses (mi.lib's nlBow): Z in N·s/m, scale the
     * velocity scale (REAL_UNITS: m/s, > 0), profile 0 (piecewise linear) or 1 (smooth).
     */
    public Bow3D addBow3D(String name, double Z, double scale, int profile, String m1, String m2) {
        return handles.link(build.addBow3D(name, Z, scale, profile, m1, m2));
    }

    /**
     * Adds a bowing friction against the relative velocity of the masses (mi.lib's nlBow): Z in N·s/m, scale the
     * velocity scale (REAL_UNITS: m/s, > 0), profile 0 (piecewise linear) or 1 (smooth).
     */
    public Bow3D addBow3D(String name, double Z, double scale, int profile, Mass m1, Mass m2) {
        String[] n = handles.distinct("addBow3D", name, m1, m2);
        return addBow3D(name, Z, scale, profile, n[0], n[1]);
    }

    /**
     * Adds a bowing friction along z (mi.lib's nlBow): Z in N·s/m, scale the velocity scale (REAL_UNITS: m/s, > 0),
     * profile 0 (piecewise linear) or 1 (smooth).
     */
    public Bow1D addBow1D(String name, double Z, double scale, int profile, String m1, String m2) {
        return handles.link(build.addBow1D(name, Z, scale, profile, m1, m2));
    }

    /**
     * Adds a bowing friction along z (mi.lib's nlBow): Z in N·s/m, scale the velocity scale (REAL_UNITS: m/s, > 0),
     * profile 0 (piecewise linear) or 1 (smooth).
     */
    public Bow1D addBow1D(String name, double Z, double scale, int profile, Mass m1, Mass m2) {
        String[] n = handles.distinct("addBow1D", name, m1, m2);
        return addBow1D(name, Z, scale, profile, n[0], n[1]);
    }

    /**
     * Adds a clipped cubic contact that pushes the masses apart while they are closer than dist (mi.lib's
     * nlCollisionClipped with s = K, c = C, k = Kmax, thres = dist); C in N/m^3, Kmax in N/m (REAL_UNITS).
     */
    public ClippedContact3D addClippedContact3D(String name, double dist, double K, double Z, double C, double Kmax,
            String m1, String m2) {
        return handles.link(build.addClippedContact3D(name, dist, K, Z, C, Kmax, m1, m2));
    }

    /**
     * Adds a clipped cubic contact that pushes the masses apart while they are closer than dist (mi.lib's
     * nlCollisionClipped with s = K, c = C, k = Kmax, thres = dist); C in N/m^3, Kmax in N/m (REAL_UNITS).
     */
    public ClippedContact3D addClippedContact3D(String name, double dist, double K, double Z, double C, double Kmax,
            Mass m1, Mass m2) {
        String[] n = handles.distinct("addClippedContact3D", name, m1, m2);
        return addClippedContact3D(name, dist, K, Z, C, Kmax, n[0], n[1]);
    }

    /**
     * Adds a clipped cubic contact along z, m2 above m1, acting while z2 - z1 is below dist (mi.lib's
     * nlCollisionClipped with s = K, c = C, k = Kmax, thres = dist); C in N/m^3, Kmax in N/m (REAL_UNITS).
     */
    public ClippedContact1D addClippedContact1D(String name, double dist, double K, double Z, double C, double Kmax,
            String m1, String m2) {
        return handles.link(build.addClippedContact1D(name, dist, K, Z, C, Kmax, m1, m2));
    }

    /**
     * Adds a clipped cubic contact along z, m2 above m1, acting while z2 - z1 is below dist (mi.lib's
     * nlCollisionClipped with s = K, c = C, k = Kmax, thres = dist); C in N/m^3, Kmax in N/m (REAL_UNITS).
     */
    public ClippedContact1D addClippedContact1D(String name, double dist, double K, double Z, double C, double Kmax,
            Mass m1, Mass m2) {
        String[] n = handles.distinct("addClippedContact1D", name, m1, m2);
        return addClippedContact1D(name, dist, K, Z, C, Kmax, n[0], n[1]);
    }

    // =================================================================== look-up

    /** {@return true when a mass with this name exists} */
    public boolean matExists(String name) {
        return query.matExists(name);
    }

    /** {@return true when at least one interaction with this name exists} */
    public boolean linkExists(String name) {
        return query.linkExists(name);
    }

    /** {@return the number of masses} */
    public int getNumberOfMats() {
        return query.getNumberOfMats();
    }

    /** {@return the number of interactions} */
    public int getNumberOfLinks() {
        return query.getNumberOfLinks();
    }

    /** {@return the index of a mass in insertion order (indices shift down after removals), or -1} */
    public int getMatIndex(String name) {
        return query.getMatIndex(name);
    }

    /** {@return the index of the first interaction with this name, in insertion order, or -1} */
    public int getLinkIndex(String name) {
        return query.getLinkIndex(name);
    }

    /** {@return the handle of a mass by name} */
    public Mass getMass(String name) {
        return query.read(() -> handles.mass(query.getMass(name))); // the id and its handle, read together
    }

    /** {@return the handle of the first interaction with this name} */
    public Interaction getInteraction(String name) {
        return query.read(() -> handles.link(query.getInteraction(name)));
    }

    /** {@return the handle of the interaction at an index (interaction names may repeat; indices do not)} */
    public Interaction getInteractionAt(int i) {
        return query.read(() -> handles.link(query.getInteractionAt(i)));
    }

    /** {@return the name of the mass at an index} */
    public String getMatNameAt(int i) {
        return query.getMatNameAt(i);
    }

    /** {@return the name of the interaction at an index} */
    public String getLinkNameAt(int i) {
        return query.getLinkNameAt(i);
    }

    /** {@return the module type of the mass at an index, for example {@code matModuleType.Mass3D}} */
    public matModuleType getMatTypeAt(int i) {
        return query.getMatTypeAt(i);
    }

    /** {@return the module type of the interaction at an index, for example {@code linkModuleType.SpringDamper3D}} */
    public linkModuleType getLinkTypeAt(int i) {
        return query.getLinkTypeAt(i);
    }

    /** {@return the names of the two masses of an interaction (the same name twice for a plane contact)} */
    public String[] getLinkMatNames(String name) {
        return query.getLinkMatNames(name);
    }

    // =================================================================== mass state

    /** {@return a copy of the position of a mass} */
    public Vect3D getMatPosition(String name) {
        return getMatPosition(name, new Vect3D());
    }

    /** Writes the position of a mass into {@code out} (no allocation) and returns it. */
    public Vect3D getMatPosition(String name, Vect3D out) {
        return state.getMatPosition(name, out);
    }

    /** {@return the position of a mass as a Processing {@code PVector} (float precision)} */
    public PVector getMatPVector(String name) {
        return getMatPosition(name).toPVector();
    }

    /** {@return the position of the mass at an index} */
    public Vect3D getMatPosAt(int i) {
        return state.getMatPosAt(i);
    }

    /** {@return the velocity of a mass, in units per second (backward difference over the last step)} */
    public Vect3D getMatVelocity(String name) {
        return state.getMatVelocity(name);
    }

    /** {@return the velocity of the mass at an index, in units per second} */
    public Vect3D getMatVelAt(int i) {
        return state.getMatVelAt(i);
    }

    /** {@return the force accumulated on a mass by the last interaction phase (REAL_UNITS: N)} */
    public Vect3D getMatForce(String name) {
        return state.getMatForce(name);
    }

    /** {@return the force on the mass at an index} */
    public Vect3D getMatFrcAt(int i) {
        return state.getMatFrcAt(i);
    }

    /** {@return the force on a mass as a Processing {@code PVector}} */
    public PVector getMatForcePVector(String name) {
        return getMatForce(name).toPVector();
    }

    /**
     * Moves a mass to a position with zero velocity. Its interactions forget the distance they saw before, so
     * that their dampers do not take the jump for a velocity (unless {@link #setMoveKeepsLinkHistory} asks for
     * the paper engine's behaviour). An oscillator's rest point stays where it is, so a displaced oscillator
     * swings back toward it; a fixed point moves for good.
     */
    public void setMatPosition(String name, Vect3D pos) {
        state.setMatPosition(name, pos);
    }

    /** Moves the mass at an index to a position with zero velocity (see {@link #setMatPosition}). */
    public void setMatPosAt(int i, Vect3D pos) {
        state.setMatPosAt(i, pos);
    }

    /**
     * Chooses what moving a mass by hand ({@link #setMatPosition}, {@link #setMatPosAt}, {@link Mass#setPosition})
     * does to its interactions' memory of the distance they saw at their last step.
     *
     * <ul>
     * <li>{@code false}, the default: they forget it and start again from the new distance, so a jump is not a
     * velocity: a mass put somewhere else starts there at rest, and no damper kicks it.</li>
     * <li>{@code true}, the paper's engine: they keep it, so in the next step each damper of the moved mass sees
     * the jump as a radial velocity and pushes against it (a force of Z × the change of distance, in per-step
     * units). A mass moved a little at every step, as the paper's PluckedString moves its plectrum, then drags
     * its dampers along as a moving mass would, and sounds as it did in the paper's engine.</li>
     * </ul>
     *
     * <p>The choice applies to moves made after the call. {@code changeDistXBetweenSubset}, ramps and
     * {@code changeToFixedPoint} always reset the history.
     *
     * @param keep true for the paper engine's behaviour
     */
    public void setMoveKeepsLinkHistory(boolean keep) {
        state.setMoveKeepsLinkHistory(keep);
    }

    /** {@return true when a position move keeps the link history, as the paper's engine did (false by default)} */
    public boolean getMoveKeepsLinkHistory() {
        return state.getMoveKeepsLinkHistory();
    }

    /** Sets the velocity of a mass, in units per second, keeping its position. */
    public void setMatVelocity(String name, Vect3D vel) {
        state.setMatVelocity(name, vel);
    }

    /** Adds a force to a mass for the next step only (REAL_UNITS: N). */
    public void triggerForceImpulse(String name, double fx, double fy, double fz) {
        state.triggerForceImpulse(name, fx, fy, fz);
    }

    /** Adds a force to the mass at an index for the next step only. */
    public void triggerForceImpulse(int i, double fx, double fy, double fz) {
        state.triggerForceImpulse(i, fx, fy, fz);
    }

    /**
     * Puts a free mass (Mass3D, Mass3DSimple, Mass2DPlane, Mass1D) under velocity control: from the next step it
     * moves at exactly (vx, vy, vz) units per second and ignores forces, friction and gravity, pushing whatever it
     * touches; a Mass2DPlane keeps its z, a Mass1D its x and y. Call it again to change the velocity.
     * {@link #stopVelocityControl(String)} releases it, still moving at that velocity: a pluck.
     */
    public void triggerVelocityControl(String name, double vx, double vy, double vz) {
        state.triggerVelocityControl(name, vx, vy, vz);
    }

    /** Puts the mass at an index under velocity control (see {@link #triggerVelocityControl(String, double, double, double)}). */
    public void triggerVelocityControl(int i, double vx, double vy, double vz) {
        state.triggerVelocityControl(i, vx, vy, vz);
    }

    /** Ends the velocity control of a mass: it keeps moving at the velocity it had, and feels forces again. */
    public void stopVelocityControl(String name) {
        state.stopVelocityControl(name);
    }

    /** Ends the velocity control of the mass at an index. */
    public void stopVelocityControl(int i) {
        state.stopVelocityControl(i);
    }

    // =================================================================== the paper engine's index queries

    /** {@return the position of the first mass of the interaction at an index (a copy)} */
    public Vect3D getLinkPos1At(int i) {
        return query.getLinkPos1At(i);
    }

    /**
     * {@return the position of the second mass of the interaction at an index (a copy); for a plane contact, the
     *     foot of its mass on the plane}
     */
    public Vect3D getLinkPos2At(int i) {
        return query.getLinkPos2At(i);
    }

    /** {@return the index of the first mass of the interaction at an index} */
    public int getLinkMat1IdxAt(int i) {
        return query.getLinkMat1IdxAt(i);
    }

    /** {@return the index of the second mass of the interaction at an index, or -1 for a plane contact} */
    public int getLinkMat2IdxAt(int i) {
        return query.getLinkMat2IdxAt(i);
    }

    /** {@return the name of the first mass of the interaction at an index} */
    public String getLinkMat1NameAt(int i) {
        return query.getLinkMat1NameAt(i);
    }

    /** {@return the name of the second mass of the interaction at an index, or "" for a plane contact} */
    public String getLinkMat2NameAt(int i) {
        return query.getLinkMat2NameAt(i);
    }

    /** {@return the position the mass at an index had one step before (a copy)} */
    public Vect3D getMatDelayedPosAt(int i) {
        return query.getMatDelayedPosAt(i);
    }

    /** {@return the force on the mass at an index as a Processing {@code PVector} (REAL_UNITS: N)} */
    public PVector getMatForcePVector(int i) {
        return query.getMatForcePVector(i);
    }

    /** {@return the distance (length units) of the oscillator at an index from its rest point} */
    public double getOsc3DDeltaPos(int i) {
        return query.getOsc3DDeltaPos(i);
    }

    /** {@return the axis (0 = x, 1 = y, 2 = z) of the plane contact at an index} */
    public int getPlaneOrientationAt(int i) {
        return query.getPlaneOrientationAt(i);
    }

    /** {@return the coordinate, on its axis, of the plane of the plane contact at an index} */
    public double getPlanePositionAt(int i) {
        return query.getPlanePositionAt(i);
    }

    // ------------------------------------------------------------- read-only queries for exporters (tactus.export)

    /**
     * {@return the rest point of an oscillator ({@code Osc3D} or {@code Osc1D}), in length units (a copy): the
     *     point its internal spring pulls it toward}
     * @throws IllegalArgumentException if the name is unknown or the mass is not an oscillator
     */
    public Vect3D getOscRestPosition(String name) {
        return query.getOscRestPosition(name);
    }

    /** {@return true while the mass is under velocity control ({@link #triggerVelocityControl})} */
    public boolean isVelocityControlled(String name) {
        return query.isVelocityControlled(name);
    }

    /** {@return the names of the mass subsets that have a contact group, in creation order (a new array)} */
    public String[] getContactGroupSubsets() {
        return query.getContactGroupSubsets();
    }

    /**
     * Replaces the content of {@code out} with the positions of every mass of one type, in index order, as float
     * {@code PVector}s (new objects).
     */
    public void getAllMatsOfType(java.util.ArrayList<PVector> out, matModuleType type) {
        query.getAllMatsOfType(out, type);
    }

    /**
     * Replaces the content of {@code pos} and {@code vel} with the positions and the displacements over the last
     * step (X - X⁻, length units per step, as in the paper's engine) of every mass of one type, in index order.
     */
    public void createPosSpeedArraysForModType(java.util.ArrayList<PVector> pos, java.util.ArrayList<PVector> vel,
                                               matModuleType type) {
        query.createPosSpeedArraysForModType(pos, vel, type);
    }

    /** The same as {@link #createPosSpeedArraysForModType}, under its older name. */
    public void getAllMatSpeedsOfType(java.util.ArrayList<PVector> pos, java.util.ArrayList<PVector> vel,
                                      matModuleType type) {
        query.getAllMatSpeedsOfType(pos, vel, type);
    }

    /**
     * Overwrites the first entries of lists made by {@link #createPosSpeedArraysForModType} with the current
     * positions and displacements; the lists must be long enough.
     */
    public void updatePosSpeedArraysForModType(java.util.ArrayList<PVector> pos, java.util.ArrayList<PVector> vel,
                                               matModuleType type) {
        query.updatePosSpeedArraysForModType(pos, vel, type);
    }

    /** Sets the inertia of every mass whose name contains {@code tag} (a substring match). */
    public void setMatParamsForName(String tag, double mass) {
        param.setMatParamsForName(tag, mass);
    }

    /**
     * Sets stiffness, damping and length parameter (in the model's units) of every interaction whose name
     * contains {@code tag} (a substring match), each where the kind has it.
     */
    public void setLinkParamsForName(String tag, double K, double Z, double dist) {
        param.setLinkParamsForName(tag, K, Z, dist);
    }

    /**
     * Lines the masses of a mass subset up along x, {@code dist} apart and centred on {@code center} (their y and
     * z taken from it), at rest, in subset order.
     */
    public void changeDistXBetweenSubset(Vect3D center, double dist, String subset) {
        build.changeDistXBetweenSubset(center, dist, subset);
    }

    /**
     * Creates (or replaces) a named {@link ParamController} that ramps one parameter of a subset over
     * {@code rampTime} seconds.
     *
     * @param paramName "mass", "stiffness", "damping", "dist" or "distX"
     */
    public void addParamController(String name, String subsetName, String paramName, float rampTime) {
        Check.name("addParamController", name);
        ParamController pc = new ParamController(this, rampTime, subsetName, paramName);
        query.read(() -> {
            controllers.put(name, pc);
            return null;
        });
    }

    /** {@return the named parameter controller, or null when there is none} */
    public ParamController getParamController(String name) {
        return query.read(() -> controllers.get(name));
    }

    /** The spelling of {@link #addParamController} used by the paper-era example sketches. */
    public void addParamControler(String name, String subsetName, String paramName, float rampTime) {
        addParamController(name, subsetName, paramName, rampTime);
    }

    /** The spelling of {@link #getParamController} used by the paper-era example sketches. */
    public ParamController getParamControler(String name) {
        return getParamController(name);
    }

    /** {@return true when a mass or link subset with this name exists} */
    boolean subsetExists(String subset) {
        return query.subsetExists(subset);
    }

    // =================================================================== mass parameters

    /** {@return the inertia of a mass (REAL_UNITS: kg)} */
    public double getMatMass(String name) {
        return param.getMatMass(name);
    }

    /** {@return the inertia of the mass at an index} */
    public double getMatMassAt(int i) {
        return param.getMatMassAt(i);
    }

    /** Sets the inertia of a mass, finite and &gt; 0. */
    public void setMatMass(String name, double mass) {
        param.setMatMass(name, mass);
    }

    /** Sets the inertia of the mass at an index. */
    public void setMatMassAt(int i, double mass) {
        param.setMatMassAt(i, mass);
    }

    /** Sets the internal stiffness of an oscillator (REAL_UNITS: N/m); its coefficients update at once. */
    public void setMatStiffness(String name, double K) {
        param.setMatStiffness(name, K);
    }

    /** Sets the internal stiffness of the oscillator at an index. */
    public void setMatStiffnessAt(int i, double K) {
        param.setMatStiffnessAt(i, K);
    }

    /** Sets the internal damping of an oscillator (REAL_UNITS: N·s/m). */
    public void setMatDamping(String name, double Z) {
        param.setMatDamping(name, Z);
    }

    /** Sets the internal damping of the oscillator at an index. */
    public void setMatDampingAt(int i, double Z) {
        param.setMatDampingAt(i, Z);
    }

    /** {@return the internal stiffness of an oscillator (REAL_UNITS: N/m)} */
    public double getMatStiffness(String name) {
        return param.getMatStiffness(name);
    }

    /** {@return the internal stiffness of the oscillator at an index (REAL_UNITS: N/m)} */
    public double getMatStiffnessAt(int i) {
        return param.getMatStiffnessAt(i);
    }

    /** {@return the internal damping of an oscillator (REAL_UNITS: N·s/m)} */
    public double getMatDamping(String name) {
        return param.getMatDamping(name);
    }

    /** {@return the internal damping of the oscillator at an index (REAL_UNITS: N·s/m)} */
    public double getMatDampingAt(int i) {
        return param.getMatDampingAt(i);
    }

    // =================================================================== interaction state and parameters

    /** {@return the current distance between the masses of an interaction (for a plane contact, the gap to the plane)} */
    public double getLinkDistance(String name) {
        return param.getLinkDistance(name);
    }

    /** {@return the distance of the interaction at an index} */
    public double getLinkDistanceAt(int i) {
        return param.getLinkDistanceAt(i);
    }

    /** {@return the elongation of an interaction: its distance minus its length parameter} */
    public double getLinkElongation(String name) {
        return param.getLinkElongation(name);
    }

    /** {@return the elongation of the interaction at an index} */
    public double getLinkElongationAt(int i) {
        return param.getLinkElongationAt(i);
    }

    /** {@return the stiffness of an interaction (REAL_UNITS: N/m)} */
    public double getLinkStiffness(String name) {
        return param.getLinkStiffness(name);
    }

    /** {@return the stiffness of the interaction at an index (REAL_UNITS: N/m)} */
    public double getLinkStiffnessAt(int i) {
        return param.getLinkStiffnessAt(i);
    }

    /** {@return the damping of an interaction (REAL_UNITS: N·s/m)} */
    public double getLinkDamping(String name) {
        return param.getLinkDamping(name);
    }

    /** {@return the damping of the interaction at an index (REAL_UNITS: N·s/m)} */
    public double getLinkDampingAt(int i) {
        return param.getLinkDampingAt(i);
    }

    /** {@return the length parameter of an interaction: rest length, threshold, radius, plane offset or limit} */
    public double getLinkDRest(String name) {
        return param.getLinkDRest(name);
    }

    /** {@return the length parameter of the interaction at an index} */
    public double getLinkDRestAt(int i) {
        return param.getLinkDRestAt(i);
    }

    /** Sets the stiffness of an interaction. */
    public void setLinkStiffness(String name, double K) {
        param.setLinkStiffness(name, K);
    }

    /** Sets the stiffness of the interaction at an index. */
    public void setLinkStiffnessAt(int i, double K) {
        param.setLinkStiffnessAt(i, K);
    }

    /** Sets the damping of an interaction. */
    public void setLinkDamping(String name, double Z) {
        param.setLinkDamping(name, Z);
    }

    /** Sets the damping of the interaction at an index. */
    public void setLinkDampingAt(int i, double Z) {
        param.setLinkDampingAt(i, Z);
    }

    /** Sets the length parameter (rest length, threshold, radius, offset or limit) of an interaction. */
    public void setLinkDRest(String name, double d) {
        param.setLinkDRest(name, d);
    }

    /** Sets the length parameter of the interaction at an index. */
    public void setLinkDRestAt(int i, double d) {
        param.setLinkDRestAt(i, d);
    }

    /** Sets stiffness, damping and length parameter of an interaction together. */
    public void setLinkParams(String name, double K, double Z, double dist) {
        param.setLinkParams(name, K, Z, dist);
    }

    // =================================================================== haptic avatar

    /** Sets the device position that a HapticInput3D (or PosInput3D) follows through its EWMA. */
    public void setHapticPosition(String name, Vect3D pos) {
        state.setHapticPosition(name, pos);
    }

    /**
     * Returns the force accumulated on a haptic avatar since the last call, summed over every step in between
     * (REAL_UNITS: N), and resets the accumulator.
     */
    public Vect3D getHapticForce(String name) {
        return state.getHapticForce(name);
    }

    /**
     * As {@link #getHapticForce(String, Vect3D)}, and returns how many model steps the force sums over, read
     * together with it (0 if no step ran since the last read): force / steps is the mean force per step even while
     * another thread steps the model in realtime and in bursts (an audio thread). Not in the paper's engine.
     */
    public long getHapticForceCounted(String name, Vect3D out) {
        return state.getHapticForceCounted(name, out);
    }

    /**
     * Writes the force accumulated on a haptic avatar since the last call into {@code out} without allocating
     * (see {@link #getHapticForce(String)}) and returns it.
     */
    public Vect3D getHapticForce(String name, Vect3D out) {
        return state.getHapticForce(name, out);
    }

    // =================================================================== topology

    /** Removes an interaction (the first one with this name). */
    public void removeLink(String name) {
        build.removeLink(name);
    }

    /** Removes the interaction at an index. */
    public void removeLink(int i) {
        build.removeLink(i);
    }

    /** Removes a mass and every interaction connected to it. */
    public void removeMatAndConnectedLinks(String name) {
        build.removeMatAndConnectedLinks(name);
    }

    /** Removes the mass at an index and every interaction connected to it. */
    public void removeMatAndConnectedLinks(int i) {
        build.removeMatAndConnectedLinks(i);
    }

    /**
     * Turns a mass into a fixed point (Ground3D) at its current position. Its interactions stay attached and
     * its name now designates the fixed point.
     *
     * @return the handle of the new fixed point
     */
    public Ground3D changeToFixedPoint(String name) {
        return handles.mass(build.changeToFixedPoint(name));
    }

    /** Removes every mass, interaction, subset and contact group; names become free again, and a diverged model may run again. */
    public void clearModel() {
        build.clearModel();
    }

    // =================================================================== subsets

    /** Creates an empty named group of masses, for grouped parameter changes. */
    public void createMatSubset(String subset) {
        build.createMatSubset(subset);
    }

    /** Creates an empty named group of interactions. */
    public void createLinkSubset(String subset) {
        build.createLinkSubset(subset);
    }

    /** Adds a mass to a mass subset. */
    public void addMatToSubset(String mass, String subset) {
        build.addMatToSubset(mass, subset);
    }

    /** Adds the mass at an index to a mass subset. */
    public void addMatToSubset(int i, String subset) {
        build.addMatToSubset(i, subset);
    }

    /** Adds an interaction (the first one with this name) to a link subset. */
    public void addLinkToSubset(String link, String subset) {
        build.addLinkToSubset(link, subset);
    }

    /** Adds the interaction at an index to a link subset. */
    public void addLinkToSubset(int i, String subset) {
        build.addLinkToSubset(i, subset);
    }

    /** Removes a mass from a mass subset. */
    public void removeMatFromSubset(String mass, String subset) {
        build.removeMatFromSubset(mass, subset);
    }

    /** Removes an interaction from a link subset. */
    public void removeLinkFromSubset(String link, String subset) {
        build.removeLinkFromSubset(link, subset);
    }

    /** {@return the names of the members of a mass or link subset, in the order they were added} */
    public String[] getSubsetMembers(String subset) {
        return build.getSubsetMembers(subset);
    }

    /** Sets the inertia of every mass in a mass subset. */
    public void changeMassParamOfSubset(double mass, String subset) {
        build.changeMassParamOfSubset(mass, subset);
    }

    /** Sets the stiffness of every member of a subset: links of a link subset, oscillators of a mass subset. */
    public void changeStiffnessParamOfSubset(double K, String subset) {
        build.changeStiffnessParamOfSubset(K, subset);
    }

    /** Sets the damping of every member of a subset: links of a link subset, oscillators of a mass subset. */
    public void changeDampingParamOfSubset(double Z, String subset) {
        build.changeDampingParamOfSubset(Z, subset);
    }

    /** Sets the length parameter (rest length, threshold, radius) of every interaction in a link subset. */
    public void changeDistParamOfSubset(double d, String subset) {
        build.changeDistParamOfSubset(d, subset);
    }

    /**
     * Sets one parameter on every member of a subset. {@code param} is "mass", "stiffness", "damping" or
     * "dist". Every member is checked before any is changed, so an error leaves the model unchanged. As in the paper's
     * engine, members without the parameter (the grounds of a mass change) are left alone, an unknown subset is
     * ignored for "stiffness" and "damping", and an unknown parameter name is ignored, each with one warning (see
     * {@link #setStrict(boolean)}).
     */
    public void changeParamOfSubset(double value, String subset, String param) {
        build.changeParamOfSubset(value, subset, param);
    }

    /**
     * The original's signature, with a {@code float} value: the same as
     * {@link #changeParamOfSubset(double, String, String)}.
     */
    public void changeParamOfSubset(float value, String subset, String param) {
        changeParamOfSubset((double) value, subset, param);
    }

    /** {@return the value of a parameter ("mass", "stiffness", "damping", "dist") for the first member of a subset} */
    public double getParamValueOfSubset(String subset, String param) {
        return build.getParamValueOfSubset(subset, param);
    }

    /** {@return the mean position of the masses of a mass subset} */
    public Vect3D getBarycenterOfSubset(String subset) {
        return build.getBarycenterOfSubset(subset);
    }

    // =================================================================== contact groups

    /**
     * Makes every pair of masses of a mass subset interact like a {@link Contact3D} with the given threshold,
     * stiffness and damping, without N² explicit links: a broad phase (a neighbour list with a skin distance,
     * built on a grid) finds the close pairs. The forces are exactly those of explicit Contact3D links added for
     * every pair (i, j), i before j in subset order. The group follows the subset: masses added to or removed
     * from it later join or leave the group.
     *
     * @param subset an existing mass subset
     * @param threshold contact distance, &gt; 0 (typically the sum of two radii)
     * @param K contact stiffness (REAL_UNITS: N/m)
     * @param Z contact damping (REAL_UNITS: N·s/m)
     */
    public void addContactGroup(String subset, double threshold, double K, double Z) {
        build.addContactGroup(subset, threshold, K, Z);
    }

    /** Changes the threshold, stiffness and damping of a subset's contact group. */
    public void setContactGroupParams(String subset, double threshold, double K, double Z) {
        build.setContactGroupParams(subset, threshold, K, Z);
    }

    /** Removes a subset's contact group (the subset itself stays). */
    public void removeContactGroup(String subset) {
        build.removeContactGroup(subset);
    }

    /** {@return true when the mass subset has a contact group} */
    public boolean hasContactGroup(String subset) {
        return build.hasContactGroup(subset);
    }

    // =================================================================== strictness

    /**
     * Chooses what the calls of the paper's API do with the mistakes the paper's engine (miPhysics) silently
     * ignored. Forgiving (false, the default): the call does what the original did, and the first time each kind of
     * problem occurs one warning goes to standard error, naming the call, the element and what was skipped. The cases: an
     * interaction from a mass to itself ({@code addBubble3D("b", ..., "gnd", "gnd")} and the other two-mass
     * {@code add...} calls: nothing is added, null is returned); a subset never created given to
     * {@code changeStiffnessParamOfSubset}, {@code changeDampingParamOfSubset}, {@code changeDistXBetweenSubset},
     * {@code getParamValueOfSubset} (returns -1) or a controller; a subset created twice; a mass or interaction that
     * is not in the model given to {@code addMatToSubset} / {@code addLinkToSubset}; a parameter a member does not
     * have (the mass of a ground in {@code changeMassParamOfSubset}, {@code setMatParamsForName},
     * {@code setMatMass(At)}; the stiffness of a Mass3D; the damping of a Spring3D ...: that member is left alone,
     * the others change; {@code getMatMassAt} on a ground returns 1, {@code getMatStiffnessAt} /
     * {@code getMatDampingAt} of a mass that is not an oscillator return 0); an unknown parameter name in
     * {@code changeParamOfSubset}; {@code setHapticPosition} / {@code getHapticForce} on a mass that is not an input;
     * an index past the end in the index getters ({@code getMatPosAt}, {@code getLinkNameAt}, ...: the original's
     * default, "None", a zero vector, -1 or 0). Nothing is ever half done: a skipped call changes nothing, a partly skipped one changes exactly the members
     * that have the parameter.
     *
     * <p>Strict (true): each of these calls throws the {@link IllegalArgumentException} that names the element and
     * the problem, and leaves the model unchanged. The calls that are Tactus's own (handles, contact groups,
     * {@code getMatMass(String)}, ...) are always strict. docs/coming-from-miphysics.md lists every case.
     *
     * @param strict true to throw, false (the default) to forgive as the paper's engine did
     */
    public void setStrict(boolean strict) {
        settings.setStrict(strict);
    }

    /** {@return true when the paper's API throws where the paper's engine forgave (see {@link #setStrict(boolean)})} */
    public boolean isStrict() {
        return settings.isStrict();
    }

    // =================================================================== stability and divergence

    /**
     * Sets what the automatic stability analysis does: it runs at {@link #init()} and after every parameter or
     * topology change made after it.
     */
    public void setStabilityPolicy(StabilityPolicy policy) {
        settings.setStabilityPolicy(policy);
    }

    /** {@return the current stability policy (WARN by default)} */
    public StabilityPolicy getStabilityPolicy() {
        return settings.getStabilityPolicy();
    }

    /**
     * Sets how many contacts the analysis assumes engaged at once on one mass (12 by default: close packing in
     * 3D; 6 suits a cubic pile, 2 a chain of beads).
     */
    public void setMaxContactsPerMass(int n) {
        settings.setMaxContactsPerMass(n);
    }

    /** {@return the stability analysis of the model as it is now (see {@link StabilityReport})} */
    public StabilityReport getStabilityReport() {
        return settings.getStabilityReport();
    }

    /** {@return one line describing the model's stability: the margin, or the offending module and its limit} */
    public String describeStability() {
        return settings.describeStability();
    }

    /**
     * Registers a listener for divergence events; with a listener, stepping calls no longer throw
     * {@link DivergenceException} but notify it once per divergence. Pass null to go back to exceptions.
     */
    public void setDivergenceListener(DivergenceListener listener) {
        settings.setDivergenceListener(listener);
    }

    /** Sets how often (in steps, &ge; 1, default 64) the running model is checked for divergence. */
    public void setDivergenceCheckInterval(int steps) {
        settings.setDivergenceCheckInterval(steps);
    }

    /** Sets the largest coordinate magnitude still considered sane (default 1e12 model length units). */
    public void setDivergenceLimit(double limit) {
        settings.setDivergenceLimit(limit);
    }

    /** {@return true when the model has diverged and is frozen} */
    public boolean isDiverged() {
        return settings.isDiverged();
    }

    /**
     * The divergence flag read without entering the model: it never takes the model's lock nor waits for another
     * thread, for the thread that steps the model (a PhyUGen's audio thread checks it between samples). On the
     * thread that steps the model it is exactly {@link #isDiverged()}; on another thread it is as of the last
     * stepping call, {@code clearDivergence()} or removal of the diverged mass that returned.
     *
     * @return true when the model has diverged and is frozen
     */
    public boolean isDivergedNow() {
        return settings.isDivergedNow();
    }

    /** Lets a diverged model step again; repair its state first (positions, parameters). */
    public void clearDivergence() {
        settings.clearDivergence();
    }

    // =================================================================== energy

    /** {@return the kinetic energy of the model (REAL_UNITS: J), from backward-difference velocities} */
    public double getKineticEnergy() {
        return query.getKineticEnergy();
    }

    /** {@return the potential energy stored in engaged springs, oscillators, attractors and gravity (REAL_UNITS: J)} */
    public double getPotentialEnergy() {
        return query.getPotentialEnergy();
    }

    /** {@return kinetic plus potential energy (REAL_UNITS: J)} */
    public double getTotalEnergy() {
        return query.getTotalEnergy();
    }
}
