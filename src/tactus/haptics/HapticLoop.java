package tactus.haptics;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.locks.LockSupport;
import java.util.regex.Pattern;
import tactus.scheduling.RealtimeThreads;
import tactus.haptics.loop.DecoupledAvatar;
import tactus.haptics.loop.HeapWarmup;
import tactus.haptics.loop.WindowHistogram;
import tactus.haptics.pantograph.PantographDevice;
import tactus.haptics.pantograph.PantographKinematics;
import tactus.haptics.passivity.HapticPort;
import tactus.haptics.passivity.FrictionCompensation;
import tactus.haptics.passivity.PassivityObserver;
import tactus.haptics.passivity.VirtualCoupling;

/**
 * The haptic loop: a dedicated thread at a fixed rate (1 kHz by default) that, each tick, reads the device,
 * runs the pantograph kinematics, sets the avatar's target, steps the model (haptics-only mode), takes the
 * avatar's force, applies the gains, and writes the torques J^T F.
 *
 * <p>Mapping (as the paper's sketches): model position = (s alpha x + ox, alpha y + oy, oz) and device force
 * = (s g beta Fx, g beta Fy), g the sign of alpha, where (x, y) is the handle in metres, s = -1 when x is mirrored (the default, as
 * the sketches draw the device seen from the user) and F the avatar force in model units: its mean per model
 * step over the steps since the last tick (in AUDIO mode, held while no audio step runs; see
 * {@link AvatarLink#takeForceCounted}).
 * {@link #useRealUnits()} sets alpha = beta = 1 for a model in REAL_UNITS (metres, newtons).
 *
 * <p>Safety: torques are scaled down to the torque limit (0.123 N m, the firmware's, by default); a
 * non-finite force, a force above the runaway limit or an unreachable pose gives zero torque in the same
 * tick; a model that throws gives zero torque and stops the loop; a watchdog thread zeroes the torque when no
 * tick has started for a set time; a lost link (or no reply for a set time) stops the loop after zeroing the
 * motors where the link still allows; {@link #close()} stops the loop and closes the board, which sends
 * zero torques (the board also does so from a JVM shutdown hook).
 *
 * <p>Timing: ticks fall on absolute deadlines (a late tick does not shift the ones after it); the thread parks
 * until {@link #setSpinMicros(int) a short time} before each deadline and spins the rest. In {@link Mode#AUDIO}
 * the loop wraps its avatar in a {@link DecoupledAvatar} by default, so that a tick never waits for the model's
 * lock while the audio thread computes a buffer. On a loaded machine the operating system still preempts the
 * thread now and then; {@link #setRealtimePriority(int)} asks Linux for real-time scheduling, which removes
 * almost all of it where the user is allowed to (see {@code docs/haptics.md} for measured figures).
 *
 * <p>Telemetry ({@link #telemetry()}): achieved rate, missed steps (a period over 1.5 times nominal), period
 * jitter p50/p99/max, compute time per tick. Configure before {@link #start()}.
 */
public final class HapticLoop implements AutoCloseable {
    /** Number of recent ticks kept for the percentiles. */
    public static final int WINDOW = 1 << 16;
    /** The threads that zero the motors when the loop stalls: this loop's watchdog and the boards' torque watchdogs. */
    /** The share of each tick period reserved for the loop thread under SCHED_DEADLINE, in percent. */
    static final int DEADLINE_SHARE_PERCENT = 80;
    static final Pattern SAFETY_THREADS = Pattern.compile("tactus-haptic-w|tactus-haply-to");
    /** The loop's watchdog thread as Linux names it (15 characters). */
    private static final Pattern LOOP_WATCHDOG_NAME = Pattern.compile("tactus-haptic-w");
    /** How long the loop thread waits for its watchdog to show up before it asks for real-time scheduling, ms. */
    private static final long WATCHDOG_NAME_WAIT_MS = 1000;

    /** Who steps the model. */
    public enum Mode {
        /** The haptic thread steps the model {@link #setStepsPerTick(int)} times per tick. */
        HAPTICS_ONLY,
        /** The audio thread steps the model; the haptic thread only moves the avatar and takes the force. */
        AUDIO
    }

    /** The device every tick runs through: the one given, or the loop's own {@link PantographDevice} over a Device. */
    private final HapticDevice spatial;
    /** The loop's own pantograph when it was built on a {@link Device} (the loop then sets its torque gain and limit), else null. */
    private final PantographDevice board;
    /** The device as a pantograph (the loop's own or one given), for the joint torques; else null. */
    private final PantographDevice pantograph;
    private final AvatarLink avatar;
    private WorkspaceMapping explicitMapping;    // set by setWorkspaceMapping, or null
    private WorkspaceMapping mapping;            // the mapping in use, fixed at start()

    private volatile double rateHz = 1000;
    private Mode mode = Mode.HAPTICS_ONLY;
    private int stepsPerTick = 1;
    private double alpha = 200;
    private double beta = 100;
    private double ox;
    private double oy;
    private double oz;
    private boolean mirrorX = true;
    private double torqueGain = 1.0;
    private double torqueLimit = BoardModel.MAX_TORQUE;
    private double forceLimit = 20;
    private int watchdogMillis = 20;
    private int linkTimeoutMillis = 500;
    private int spinMicros = 60;
    private int realtimePriority;
    private boolean realtimeJvmThreads = true;
    private boolean deadlineScheduling = true;
    private boolean heapWarmup = true;
    private boolean decoupleInAudioMode = true;
    private boolean realUnits;
    private volatile String scheduling = "not started";
    private AvatarLink active;
    /** The link whose beginStepping() the last start() called, until stop() ends it. */
    private volatile AvatarLink stepping;
    private DecoupledAvatar ownDecoupler;
    /** Between the device and the avatar: the passivity observer and controller, coupling, friction compensation. */
    private final HapticPort port = new HapticPort();

    private volatile boolean running;
    private volatile Thread thread;
    private volatile Thread watchdog;
    private volatile String failure;
    private volatile long lastTickStart;
    private volatile boolean warmingUp;   // before the first tick: the real-time request and the first read

    // written by the loop thread, read by anyone (plain longs: statistics)
    private final WindowHistogram jitters = new WindowHistogram(WINDOW);
    private final WindowHistogram computes = new WindowHistogram(WINDOW);
    private volatile long ticks;
    private long startNanos;
    private volatile long lastNanos;
    private long missed;
    private long jitterMax;
    private long computeMax;
    private long stale;
    private long faults;
    private volatile long watchdogTrips;

    // per-tick state, loop thread only
    private final double[] force = new double[3];
    private final double[] portTarget = new double[3];
    private final double[] quantum = new double[3];   // the device's position quantum this tick, m
    private volatile boolean contactPlay;
    private final double[] pos3 = new double[3];
    private final double[] model3 = new double[3];
    private final double[] held3 = new double[3];   // the force per step being rendered (model units)
    private final double[] force3 = new double[3];
    private int staleRun;
    // the last tick's handle and force, read by anyone
    private volatile double devX = Double.NaN;
    private volatile double devY = Double.NaN;
    private volatile double devZ = Double.NaN;
    private volatile double forceX;
    private volatile double forceY;
    private volatile double forceZ;

    /**
     * Creates a loop over a configured device (encoders 1, 2 give theta1, theta2; actuators 1, 2 take tau1,
     * tau2), the pantograph kinematics, and a model's avatar. The loop drives them as a {@link PantographDevice}
     * of its own, with its own torque gain and limit ({@link #setTorqueGain}, {@link #setTorqueLimit}) and the
     * paper's mapping (alpha, beta, origin, mirrored x).
     */
    public HapticLoop(Device device, PantographKinematics kinematics, AvatarLink avatar) {
        if (device == null || kinematics == null || avatar == null) {
            throw new IllegalArgumentException("HapticLoop: device, kinematics and avatar must not be null, got "
                    + device + ", " + kinematics + ", " + avatar);
        }
        this.board = new PantographDevice(device, kinematics);
        this.spatial = board;
        this.pantograph = board;
        this.avatar = avatar;
    }

    /**
     * Creates a loop over any {@link HapticDevice} (an Inverse3 through the Inverse Service, or a
     * {@link PantographDevice}) and a model's avatar. Positions reach the model through a
     * {@link WorkspaceMapping}: the one given to {@link #setWorkspaceMapping}, or else the device's
     * {@linkplain HapticDevice#defaultMapping() default axes} with scale alpha ({@link #setPositionGain}) and
     * the offset of {@link #setOrigin} ({@link #setMirrorX} applies to a planar device, whose default axes are the
     * paper's mirrored ones, and not to a 3-D device, whose axes say it). Forces go back along
     * the same axes times beta ({@link #setForceGain}); the safety rules are those of every loop: a
     * non-finite force or one above the runaway limit gives zero force in the same tick, a model that throws
     * gives zero force and stops the loop, the watchdog zeroes the force, and a lost link or a device silent for
     * the link timeout stops the loop with a message.
     */
    public HapticLoop(HapticDevice device, AvatarLink avatar) {
        if (device == null || avatar == null) {
            throw new IllegalArgumentException("HapticLoop: device and avatar must not be null, got " + device + ", " + avatar);
        }
        this.board = null;
        this.spatial = device;
        this.pantograph = device instanceof PantographDevice ? (PantographDevice) device : null;
        this.avatar = avatar;
        int bound = device.lateAnswerBound();
        port.setLateBound(Math.max(0, Math.min(bound, HapticPort.MAX_LATE)));
    }

    /**
     * Sets how the device's metres map into the model (a loop built on a {@link HapticDevice} only; units per metre,
     * offset in model units), replacing the default axes, alpha and origin. {@link #useRealUnits()} then keeps its axes and offset and
     * sets its scale to 1.
     */
    public void setWorkspaceMapping(WorkspaceMapping m) {
        beforeStart("setWorkspaceMapping");
        if (m == null) {
            throw new IllegalArgumentException("HapticLoop.setWorkspaceMapping: mapping must not be null");
        }
        if (board != null) {
            throw new IllegalStateException("HapticLoop.setWorkspaceMapping: this loop drives a Device through its "
                    + "pantograph kinematics; use setPositionGain, setOrigin and setMirrorX, or build the loop on a HapticDevice");
        }
        explicitMapping = m;
    }

    /**
     * The mapping from the device's metres to the model of a loop built on a {@link HapticDevice}: the one in use
     * once started, else the one {@code start()} would use; null for a loop built on a {@link Device}.
     */
    public WorkspaceMapping workspaceMapping() {
        if (board != null) {
            return null;
        }
        WorkspaceMapping m = mapping;
        return m != null ? m : effectiveMapping();
    }

    private WorkspaceMapping effectiveMapping() {
        if (explicitMapping != null) {
            return realUnits ? explicitMapping.withScale(1) : explicitMapping;
        }
        WorkspaceMapping m = spatial.defaultMapping().withScale(alpha).withOffset(ox, oy, oz);
        // a planar device's default axes are the paper's (x mirrored); setMirrorX(false) unmirrors them
        return spatial.dimensions() == 2 && !mirrorX ? m.mirrored(0) : m;
    }

    /** The device of a loop built on a {@link HapticDevice}, or null for one built on a {@link Device}. */
    public HapticDevice hapticDevice() {
        return board != null ? null : spatial;
    }

    /** Sets the rate in Hz (1..10000; default 1000). */
    public void setRate(double hz) {
        beforeStart("setRate");
        if (!(hz >= 1 && hz <= 10_000)) {
            throw new IllegalArgumentException("HapticLoop.setRate: rate must be 1..10000 Hz, got " + hz);
        }
        rateHz = hz;
    }

    /** Sets who steps the model (default HAPTICS_ONLY). */
    public void setMode(Mode mode) {
        beforeStart("setMode");
        if (mode == null) {
            throw new IllegalArgumentException("HapticLoop.setMode: mode must not be null");
        }
        this.mode = mode;
    }

    /** Sets how many model steps a tick runs in HAPTICS_ONLY mode (>= 1; default 1). */
    public void setStepsPerTick(int n) {
        beforeStart("setStepsPerTick");
        if (n < 1) {
            throw new IllegalArgumentException("HapticLoop.setStepsPerTick: must be >= 1, got " + n);
        }
        stepsPerTick = n;
    }

    /**
     * Sets the position gain alpha (model units per metre; finite, != 0; default 200). A negative gain flips
     * both axes (with {@link #setMirrorX(boolean) setMirrorX(false)}, a model whose y axis points the other
     * way); the force is sent back along the same axes, so the rendering stays passive.
     */
    public void setPositionGain(double alpha) {
        beforeStart("setPositionGain");
        if (!Double.isFinite(alpha) || alpha == 0) {
            throw new IllegalArgumentException("HapticLoop.setPositionGain: alpha must be finite and non-zero, got " + alpha);
        }
        this.alpha = alpha;
    }

    /** Sets the force gain beta (newtons per model force unit; finite, >= 0; default 100). */
    public void setForceGain(double beta) {
        beforeStart("setForceGain");
        if (!(beta >= 0) || !Double.isFinite(beta)) {
            throw new IllegalArgumentException("HapticLoop.setForceGain: beta must be a finite number >= 0, got " + beta);
        }
        this.beta = beta;
    }

    /** Sets the model position of the device origin (model units). */
    public void setOrigin(double x, double y, double z) {
        beforeStart("setOrigin");
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z)) {
            throw new IllegalArgumentException("HapticLoop.setOrigin: must be finite, got (" + x + ", " + y + ", " + z + ")");
        }
        ox = x;
        oy = y;
        oz = z;
    }

    /** Mirrors x between device and model (default true, as the paper's sketches). */
    public void setMirrorX(boolean mirror) {
        beforeStart("setMirrorX");
        mirrorX = mirror;
    }

    /**
     * Calibrated mode for a model in REAL_UNITS: alpha = 1 (metres), beta = 1 (newtons), torque gain 1, no
     * mirroring, so a 1 g virtual mass weighs 1 g in the hand (within the device's own inertia and friction).
     * The loop renders the mean force per model step since the last tick in both modes (in AUDIO mode, held
     * between the audio thread's bursts), so no other factor is needed. (An {@link AvatarLink} that cannot
     * count its steps gets its sum rendered as it comes; then set beta to haptic rate / audio rate.)
     */
    public void useRealUnits() {
        beforeStart("useRealUnits");
        alpha = 1;
        beta = 1;
        torqueGain = 1;
        mirrorX = false;
        realUnits = true;
    }

    /** Sets the gain on J^T F (default 1: physical torques; hAPI's 2018 Pantograph used 0.1 / l). */
    public void setTorqueGain(double gain) {
        beforeStart("setTorqueGain");
        if (!(gain >= 0) || !Double.isFinite(gain)) {
            throw new IllegalArgumentException("HapticLoop.setTorqueGain: gain must be a finite number >= 0, got " + gain);
        }
        torqueGain = gain;
    }

    /**
     * Sets the largest joint torque in N m (0 &lt; limit &lt;= 0.123; default 0.123, the firmware's clip); when a
     * joint torque is larger, both are scaled down by the same factor, so the force keeps its direction. A
     * limit above the firmware's clip is refused: the firmware would clip each motor alone and turn the force.
     */
    public void setTorqueLimit(double nm) {
        beforeStart("setTorqueLimit");
        if (!(nm > 0) || !Double.isFinite(nm)) {
            throw new IllegalArgumentException("HapticLoop.setTorqueLimit: limit must be a finite number > 0 N m, got " + nm);
        }
        if (nm > BoardModel.MAX_TORQUE) {
            throw new IllegalArgumentException("HapticLoop.setTorqueLimit: limit " + nm + " N m is above the firmware's "
                    + "clip of " + BoardModel.MAX_TORQUE + " N m, which clips each motor alone and turns the force; "
                    + "use a limit up to " + BoardModel.MAX_TORQUE + " N m");
        }
        torqueLimit = nm;
    }

    /** Sets the runaway force in newtons (> 0; default 20): a larger device force gives zero torque. */
    public void setForceLimit(double newtons) {
        beforeStart("setForceLimit");
        if (!(newtons > 0) || !Double.isFinite(newtons)) {
            throw new IllegalArgumentException("HapticLoop.setForceLimit: limit must be a finite number > 0 N, got " + newtons);
        }
        forceLimit = newtons;
    }

    /** Sets after how many milliseconds without a tick the watchdog zeroes the torque (>= 1; default 20). */
    public void setWatchdogMillis(int ms) {
        beforeStart("setWatchdogMillis");
        if (ms < 1) {
            throw new IllegalArgumentException("HapticLoop.setWatchdogMillis: must be >= 1 ms, got " + ms);
        }
        watchdogMillis = ms;
    }

    /** Sets after how many milliseconds without a reply the link counts as lost (>= 1; default 500). */
    public void setLinkTimeoutMillis(int ms) {
        beforeStart("setLinkTimeoutMillis");
        if (ms < 1) {
            throw new IllegalArgumentException("HapticLoop.setLinkTimeoutMillis: must be >= 1 ms, got " + ms);
        }
        linkTimeoutMillis = ms;
    }

    /** Sets how long before each tick the thread spins instead of sleeping, in microseconds (0..1000; default 60). */
    public void setSpinMicros(int us) {
        beforeStart("setSpinMicros");
        if (us < 0 || us > 1000) {
            throw new IllegalArgumentException("HapticLoop.setSpinMicros: must be 0..1000 us, got " + us);
        }
        spinMicros = us;
    }

    /**
     * Asks for real-time scheduling (Linux SCHED_FIFO at this priority, 1..99) for the loop thread, or not (0,
     * the default). The loop thread asks once, before its first tick, through the {@code chrt} program; where
     * the user may not raise priorities (no root, no {@code CAP_SYS_NICE}, no {@code rtprio} limit) or on
     * another system, the loop runs at normal priority and {@link #scheduling()} says why. Under real-time
     * scheduling other programs no longer preempt the loop; it still sleeps between ticks, so it takes a core
     * only for its compute time plus the spin ({@link #setSpinMicros(int)}).
     */
    public void setRealtimePriority(int priority) {
        beforeStart("setRealtimePriority");
        if (priority < 0 || priority > 99) {
            throw new IllegalArgumentException("HapticLoop.setRealtimePriority: priority must be 0 (off) or 1..99, got "
                    + priority);
        }
        realtimePriority = priority;
    }

    /**
     * With real-time scheduling ({@link #setRealtimePriority(int)}), also moves the JVM's own threads that a Java
     * thread can end up waiting for to SCHED_FIFO (true, the default): the VM thread and the collector's pause
     * workers one priority below the loop, the JIT compiler threads at priority 1 (below any other real-time
     * program, such as a sound server). Or leaves them at normal priority (false). Every collection stops the loop
     * for its whole pause, and the loop's code takes locks that the compilers hold while they work; at normal
     * priority, on a loaded machine, these threads share the cores with every other program: collections of 3 ms
     * were measured to last up to 257 ms, and ticks waited up to 126 ms for a compiler. The cost: a collection or a
     * burst of compilation (mostly in the first seconds) now runs ahead of the machine's other programs. The
     * collector's concurrent threads are never moved. Configure before {@link #start()}.
     */
    public void setRealtimeJvmThreads(boolean on) {
        beforeStart("setRealtimeJvmThreads");
        realtimeJvmThreads = on;
    }

    /**
     * With real-time scheduling ({@link #setRealtimePriority(int)}), asks first for Linux's SCHED_DEADLINE for the
     * loop thread (true, the default): a reservation of 80 % of each tick period, with the period as its deadline,
     * which runs ahead of every SCHED_FIFO thread and of the kernel's reservation for starved normal threads (the
     * "fair server", 50 ms a second, which otherwise stops a SCHED_FIFO loop for up to 50 ms whenever real-time
     * threads such as the JIT compilers kept a core busy for most of a second). Where the deadline policy is refused
     * (an older kernel or chrt, the JVM pinned to some CPUs, the deadline bandwidth of the system taken), the loop
     * falls back to SCHED_FIFO at its priority, as with false. A tick that needs more than its reservation waits
     * for the next period. Configure before {@link #start()}.
     */
    public void setDeadlineScheduling(boolean on) {
        beforeStart("setDeadlineScheduling");
        deadlineScheduling = on;
    }

    /**
     * With real-time scheduling ({@link #setRealtimePriority(int)}), makes short-lived garbage at the first
     * {@link #start()} of this JVM until the collector has run three times (at most 256 MB, about 0.1-0.3 s), so
     * that a fresh JVM's first collections, which are the slow ones (37-56 ms measured under load, against 1-3 ms
     * later), happen before the loop runs rather than in the hand's first seconds (true, the default). Configure
     * before {@link #start()}.
     */
    public void setHeapWarmup(boolean on) {
        beforeStart("setHeapWarmup");
        heapWarmup = on;
    }

    /**
     * In {@link Mode#AUDIO}, wraps the avatar in a {@link DecoupledAvatar} at {@link #start()} (true, the
     * default) so that a tick never waits for the model's lock, or calls the avatar directly (false). An
     * avatar that is already a {@code DecoupledAvatar} is never wrapped twice, and one that says it
     * {@linkplain AvatarLink#neverWaits() never waits} is never wrapped. Ignored in HAPTICS_ONLY mode.
     */
    public void setDecoupledInAudioMode(boolean decouple) {
        beforeStart("setDecoupledInAudioMode");
        decoupleInAudioMode = decouple;
    }

    /**
     * How the loop thread is scheduled: "not started", "normal priority", "real-time (SCHED_DEADLINE r us of every
     * p us; safety threads at SCHED_FIFO n)" or, where the deadline policy was refused or not asked for,
     * "real-time (SCHED_FIFO n)" (each with "; VM and GC threads at n-1, JIT compilers at 1" when those were moved
     * too), or "normal priority (real-time refused: why)".
     */
    public String scheduling() {
        return scheduling;
    }

    /** True if, in this configuration, the ticks reach the avatar through a {@link DecoupledAvatar}. */
    public boolean isDecoupled() {
        return avatar instanceof DecoupledAvatar
                || (mode == Mode.AUDIO && decoupleInAudioMode && !avatar.neverWaits());
    }

    /** Starts the loop thread and its watchdog. The device must be set up. */
    public synchronized void start() {
        if (thread != null) {
            throw new IllegalStateException("HapticLoop.start: already started");
        }
        if (!deviceReady()) {
            throw new IllegalStateException(board != null
                    ? "HapticLoop.start: call device_set_parameters() on the device first"
                    : "HapticLoop.start: the device is not ready: " + spatial.describe() + ", " + spatial.status());
        }
        mapping = effectiveMapping();
        if (board != null) {
            board.setTorqueGain(torqueGain);
            board.setTorqueLimit(torqueLimit);
        }
        port.start(1.0 / rateHz);
        if (mode == Mode.AUDIO && decoupleInAudioMode && !(avatar instanceof DecoupledAvatar) && !avatar.neverWaits()) {
            ownDecoupler = new DecoupledAvatar(avatar);
            active = ownDecoupler;
        } else {
            active = avatar;
        }
        if (mode == Mode.HAPTICS_ONLY) {
            active.beginStepping();
            stepping = active;
        }
        if (realtimePriority > 0 && heapWarmup) {
            HeapWarmup.once();
        }
        running = true;
        warmingUp = true;
        Thread t = new Thread(this::run, "tactus-haptic-loop");
        t.setDaemon(true);
        t.setPriority(Thread.MAX_PRIORITY);
        thread = t;
        Thread w = new Thread(this::watch, "tactus-haptic-watchdog");
        w.setDaemon(true);
        watchdog = w;
        lastTickStart = System.nanoTime();
        t.start();
        w.start();
    }

    /** Stops the loop (waits for it) and sends zero torques; the board stays open. */
    public void stop() {
        running = false;
        Thread t = thread;
        if (t != null && t != Thread.currentThread()) {
            try {
                t.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        Thread w = watchdog;
        if (w != null) {
            w.interrupt();
        }
        zeroOutput();
        AvatarLink st = stepping;
        if (st != null && (t == null || !t.isAlive())) {
            stepping = null;
            st.endStepping();
        }
        DecoupledAvatar d = ownDecoupler;
        if (d != null) {
            d.close();
        }
    }

    /** Stops the loop and closes the board (zero torques, then the port). */
    @Override
    public void close() {
        stop();
        closeDevice();
    }

    /** Same as {@link #close()}, for Processing's dispose. */
    public void dispose() {
        close();
    }

    /** The rate in Hz. */
    public double rate() {
        return rateHz;
    }

    /** Who steps the model. */
    public Mode mode() {
        return mode;
    }

    /** The position gain alpha (model units per metre). */
    public double positionGain() {
        return alpha;
    }

    /** The force gain beta (newtons per model force unit). */
    public double forceGain() {
        return beta;
    }

    /** True if x is mirrored between device and model. */
    public boolean isMirrorX() {
        return mirrorX;
    }

    /**
     * Maps a handle position (metres, device coordinates) to the model position the avatar is sent to, as each
     * tick does: writes (s alpha x + ox, alpha y + oy) into out[0], out[1].
     */
    public void deviceToModel(double x, double y, double[] out) {
        double sx = mirrorX ? -1 : 1;
        out[0] = sx * alpha * x + ox;
        out[1] = alpha * y + oy;
    }

    /** The inverse of {@link #deviceToModel}: the handle position (metres) that puts the avatar at (mx, my). */
    public void modelToDevice(double mx, double my, double[] out) {
        double sx = mirrorX ? -1 : 1;
        out[0] = sx * (mx - ox) / alpha;
        out[1] = (my - oy) / alpha;
    }

    /** True while the loop thread runs. */
    public boolean isRunning() {
        return running;
    }

    /** Why the loop stopped by itself (lost link, model failure), or null. */
    public String failure() {
        return failure;
    }

    /**
     * The handle position of the last tick in metres, written into out[0], out[1] (and out[2], if out has room:
     * z of a 3-D device, 0 for a pantograph).
     */
    public void devicePosition(double[] out) {
        out[0] = devX;
        out[1] = devY;
        if (out.length > 2) {
            out[2] = devZ;
        }
    }

    /**
     * The device force (N) of the last tick, written into out[0], out[1] (and out[2], if out has room), zero when
     * a fault was caught.
     */
    public void deviceForce(double[] out) {
        out[0] = forceX;
        out[1] = forceY;
        if (out.length > 2) {
            out[2] = forceZ;
        }
    }

    /** The torque (N m) sent to joint j (1 or 2) at the last tick. */
    public double torque(int joint) {
        return pantograph != null ? pantograph.torque(joint) : 0;
    }

    /**
     * Switches the time-domain passivity controller on or off, at any time (also while the loop runs; default off).
     * When on, the loop adds a damper to the force whenever the {@linkplain #passivity() observer} sees the port give
     * the hand more energy than it took (Hannaford &amp; Ryu 2002): a stiff wall that would buzz or bounce settles,
     * and the hand never receives energy the model did not hold. A soft model that stays passive is not touched:
     * measured figures are in docs/haptics-stability.md.
     */
    public void setPassivityControl(boolean on) {
        port.setControl(on);
    }

    /** True while the passivity controller is on. */
    public boolean isPassivityControl() {
        return port.isControl();
    }

    /**
     * The passivity observer: the energy (J, at the handle) that flowed into the model and back to the hand since the
     * loop started, and the controller's activity. Read it from any thread, without a lock.
     */
    public PassivityObserver passivity() {
        return port.observer();
    }

    /**
     * Sets the largest damping (N s/m; finite, > 0; default 10) the passivity controller may add in one tick. More
     * dissipates a burst of energy faster; too much, applied a tick late, shakes a light handle. A good value is near
     * m / (T (d + 1/2)) for a handle (and hand) of mass m, period T and d ticks of exchange delay: the default suits
     * the 2DIY (about 0.02 kg along an axis, measured on the emulator); a heavier device takes more.
     */
    public void setPassivityDampingLimit(double nsPerM) {
        beforeStart("setPassivityDampingLimit");
        if (!(nsPerM > 0) || !Double.isFinite(nsPerM)) {
            throw new IllegalArgumentException("HapticLoop.setPassivityDampingLimit: limit must be a finite number > 0 N s/m, got "
                    + nsPerM);
        }
        port.setDampingLimit(nsPerM);
    }

    /**
     * Tells the passivity observer how many ticks pass between a position reading and the force sent at that tick
     * taking effect at the handle (0..8; default 0, a hold alone), so that it charges each displacement to the force
     * that acted over it. Configure before {@link #start()}.
     */
    public void setExchangeDelay(int ticks) {
        beforeStart("setExchangeDelay");
        if (ticks < 0 || ticks > HapticPort.MAX_DELAY) {
            throw new IllegalArgumentException("HapticLoop.setExchangeDelay: delay must be 0.." + HapticPort.MAX_DELAY
                    + " ticks, got " + ticks);
        }
        port.setDelay(ticks);
    }

    /**
     * Tells the passivity observer and controller that a state may answer the force it follows up to this many ticks
     * late (0..16; 0: off, every new state answers the previous tick's force, or {@link #setExchangeDelay} ticks
     * before): a tick whose device reports no new state then adds no work and keeps its force in flight, and the
     * displacement between two new states is charged with the force, among those sent from this many ticks before the
     * earlier state up to the later one, that puts the least energy into the model (conservative: the observer then
     * never reports more energy into the model than a straight-line motion under any of those forces would have put
     * in). The default is the device's {@link HapticDevice#lateAnswerBound()} (4 for an Inverse3 through the Inverse
     * Service; 0 for the 2DIY's board, whose account stays the exact fixed-delay one). Configure before
     * {@link #start()}.
     */
    public void setLateAnswerBound(int ticks) {
        beforeStart("setLateAnswerBound");
        if (ticks < 0 || ticks > HapticPort.MAX_LATE) {
            throw new IllegalArgumentException("HapticLoop.setLateAnswerBound: bound must be 0.." + HapticPort.MAX_LATE
                    + " ticks, got " + ticks);
        }
        port.setLateBound(ticks);
    }

    /** The bound on late answers (ticks) the passivity observer assumes; 0 when off. */
    public int lateAnswerBound() {
        return port.lateBound();
    }

    /** The exchange delay (ticks) the passivity observer assumes. */
    public int exchangeDelay() {
        return port.delay();
    }

    /** The largest damping (N s/m) the passivity controller may add in one tick. */
    public double passivityDampingLimit() {
        return port.dampingLimit();
    }

    /**
     * Puts a {@link VirtualCoupling} between the handle and the avatar (null: none, the default): the avatar follows
     * a proxy that the coupling's spring-damper ties to the handle, and the hand feels the coupling. At any time, also
     * while the loop runs: the loop takes the new coupling at its next tick (nothing is allocated on its thread), with
     * the proxy placed at the handle and moving with it, so the coupling starts with zero force (bumpless). Switched
     * off (null), the avatar goes back to the handle at the next tick: whatever the proxy's stretch was shows as a
     * step of the avatar in the model.
     */
    public void setVirtualCoupling(VirtualCoupling coupling) {
        port.setCoupling(coupling);
    }

    /**
     * Caps the energy (J at the handle; >= 0, or {@code Double.POSITIVE_INFINITY} for no cap) that the passivity
     * controller keeps in reserve, at any time. Without a cap, energy the hand put into the model long ago (pushing
     * through a damper, say) lets a later stiff contact give that much back before the controller acts; with it, at
     * most this much. Keep it above the energy the model itself stores and honestly gives back (a mass set swinging,
     * a spring wound up), or the controller brakes that return. The default (0.1 J) was measured not to change the
     * paper's soft examples (docs/haptics-stability.md).
     *
     * @throws IllegalArgumentException naming the value when it is negative or NaN
     */
    public void setPassivityReserveLimit(double joules) {
        if (!(joules >= 0)) {
            throw new IllegalArgumentException("HapticLoop.setPassivityReserveLimit: limit must be >= 0 J (or infinite), got "
                    + joules);
        }
        port.setReserveLimit(joules);
    }

    /**
     * Lets the port give the hand up to this much energy (J at the handle; finite, >= 0; default 0) more than it took
     * before the passivity controller damps, at any time: the port then stays passive with that much energy stored at
     * the start (the usual definition of passivity). A small tolerance keeps the controller from chasing the energy an
     * encoder's steps seem to create, which through a stiff {@link VirtualCoupling} it dissipates in bursts of force
     * at its damping limit (a buzz): 1 mJ removed them on the emulated 2DIY with a pen grip (docs/haptics-stability.md).
     *
     * @throws IllegalArgumentException naming the value when it is negative, infinite or NaN
     */
    public void setPassivityTolerance(double joules) {
        if (!(joules >= 0) || !Double.isFinite(joules)) {
            throw new IllegalArgumentException("HapticLoop.setPassivityTolerance: tolerance must be a finite number >= 0 J, got "
                    + joules);
        }
        port.setTolerance(joules);
    }

    /** The energy (J) the port may give back before the passivity controller damps. */
    public double passivityTolerance() {
        return port.tolerance();
    }

    /** The cap (J) on the energy the passivity controller keeps in reserve; infinite when there is none. */
    public double passivityReserveLimit() {
        return port.reserveLimit();
    }

    /**
     * The stiffness (N/m at the handle) {@link #useStiffContacts} is given for a stiff wall held with a pen grip on a
     * 2DIY at 1 kHz: the stiffest the energy bound renders there without a force step above 0.5 N between ticks and
     * with the hand never getting energy back, measured on the emulated plant (docs/haptics-stability.md, "Stiff
     * contacts").
     */
    public static final double TWO_DIY_STIFF_CONTACT = 1600;
    /**
     * The stiffness (N/m at the handle) {@link #useStiffContacts} is given for a stiff wall on a 3-DoF device that senses
     * position finely (an Inverse3) at 1 kHz: every case of the adversarial suite (grips from a stiff pinch to a loose
     * hold, walls switched on, moved and stiffened around the handle, taps and presses, with and without friction)
     * passes at it on the emulated 3-DoF plant (0.2 kg, 0.5 N s/m: assumed, not measured on a device), and the pen grip
     * feels about 3.3 kN/m holding (docs/haptics-stability.md, "On the 3-DoF plant").
     */
    public static final double INVERSE3_STIFF_CONTACT = 3300;
    /** The energy bound's trim ratio {@link #useStiffContacts} sets. */
    private static final double STIFF_CONTACT_TRIM = 2;
    /** The energy bound's seed {@link #useStiffContacts} sets, J. */
    private static final double STIFF_CONTACT_SEED = 1e-5;
    /** The largest change of the force per tick {@link #useStiffContacts} sets, N. */
    private static final double STIFF_CONTACT_RISE = 0.5;

    /**
     * Sets the recommended configuration for stiff walls on this loop's device, at any time: {@link
     * #useStiffContacts(double)} at {@link #TWO_DIY_STIFF_CONTACT} on a planar device (a 2DIY), at {@link
     * #INVERSE3_STIFF_CONTACT} on a 3-DoF one (an Inverse3), with the energy bound's {@linkplain
     * #setEnergyBoundCountReserve count reserve} at {@link #ROBUST_COUNT_RESERVE} (it acts only on a sensor with coarse
     * counts, such as the 2DIY's encoders). The hand then gets no energy back in any case of the adversarial suite on
     * either emulated device; on the 2DIY the walls are felt softer than with {@code useStiffContacts(stiffness)} alone
     * (about 520 against 1050 N/m with a pen grip) but a wall with friction is never lost (docs/haptics-stability.md).
     */
    public void useStiffContacts() {
        useStiffContacts(recommendedStiffContact());
        port.setEnergyBoundCountReserve(ROBUST_COUNT_RESERVE);
    }

    /**
     * {@return the stiffness (N/m at the handle) {@link #useStiffContacts()} sets on this loop's device:
     * {@link #TWO_DIY_STIFF_CONTACT} on a planar device, {@link #INVERSE3_STIFF_CONTACT} on a 3-DoF one}
     */
    public double recommendedStiffContact() {
        return spatial.dimensions() == 2 ? TWO_DIY_STIFF_CONTACT : INVERSE3_STIFF_CONTACT;
    }

    /**
     * Sets the energy-bound configuration for stiff walls and contacts, at any time (also while the loop runs): the
     * energy bound at this stiffness (N/m at the handle), the force allowed to change by at most 0.5 N per tick, its
     * budget trimmed to twice what the force holds ({@link #setEnergyBoundTrim}), the {@linkplain #setHoldCompensation
     * hold compensation} (used where the sensor is fine: the Inverse3, not the 2DIY), the passivity controller off and
     * no virtual coupling. The hand then feels every contact as at most this stiff (a
     * stiffer wall of the model is felt as this stiffness), never gets back more energy than it put in, and a wall that
     * appears or moves around the handle does not push it out. Give it the stiffest contact your device renders
     * without buzz ({@link #TWO_DIY_STIFF_CONTACT} for the 2DIY at 1 kHz, {@link #INVERSE3_STIFF_CONTACT} for an
     * Inverse3). On a Haply board, also
     * {@code setExchangeDelay(1)} before {@link #start()}, so that the energy account charges each displacement to the
     * force that acted over it.
     *
     * <p>It also switches the {@linkplain #setContactPlay contact play} on. On the emulated 3-DoF plant every case of
     * the adversarial suite passes at {@link #INVERSE3_STIFF_CONTACT}. Known failures, measured on the emulated
     * 2DIY (docs/haptics-stability.md, "The adversarial suite"), where the encoders' counts limit the bound: the wall
     * can be lost (no force at all) in slow presses, with a loose hold, on a device without friction, and for contacts
     * softer than this stiffness. For a wall that must never be lost, add the energy bound's {@linkplain
     * #setEnergyBoundCountReserve count reserve} (walls with friction are then kept, felt softer; {@link
     * #useStiffContacts()} does) or use the grip coupling ({@link VirtualCoupling#forContacts}) with the passivity
     * controller. This call leaves the count reserve as it is.
     *
     * @param stiffness the largest stiffness felt, N/m at the handle (finite, &gt; 0)
     * @throws IllegalArgumentException naming the value when it is not a finite number &gt; 0; nothing changes then
     */
    public void useStiffContacts(double stiffness) {
        if (!(stiffness > 0) || !Double.isFinite(stiffness)) {
            throw new IllegalArgumentException("HapticLoop.useStiffContacts: stiffness must be a finite number > 0 N/m"
                    + " (the stiffest contact the hand should feel, e.g. HapticLoop.TWO_DIY_STIFF_CONTACT), got " + stiffness);
        }
        port.setControl(false);
        port.setCoupling(null);
        port.setEnergyBoundSeed(STIFF_CONTACT_SEED);
        port.setForceRiseLimit(STIFF_CONTACT_RISE);
        port.setEnergyBoundTrim(STIFF_CONTACT_TRIM);
        port.setHoldCompensation(true);
        contactPlay = true;
        port.setEnergyBound(stiffness);
    }

    /** The play {@link #setContactPlay} sets, in sensor counts at the handle. */
    public static final double CONTACT_PLAY_COUNTS = 1.1;

    /**
     * Sets whether the avatar follows the handle through a play of {@value #CONTACT_PLAY_COUNTS} sensor counts (the
     * device's {@link HapticDevice#positionQuantum} at the current pose) while the {@linkplain #setEnergyBound energy
     * bound} is on and no coupling is set, at any time; {@link #useStiffContacts} switches it on. A reading that
     * flickers by one count then leaves the model's force as it is: without the play, each flicker steps the force by
     * the contact's stiffness times a count, and the energy bound charges each such step, so that a wall held still
     * drains its budget and is lost. On a device whose quantum is 0 (the Inverse3) it changes nothing.
     */
    public void setContactPlay(boolean on) {
        contactPlay = on;
    }

    /** Whether the contact play is on ({@link #setContactPlay}). */
    public boolean isContactPlay() {
        return contactPlay;
    }

    /**
     * Bounds the force sent by the energy the hand put in through the port, as a spring of this stiffness (N/m at the
     * handle; finite, &gt;= 0; 0, the default, switches it off), at any time: the force never holds more energy than
     * {@code F^2 / (2 K)} allows, so no contact gives the hand back more than it took (up to a seed of 10 µJ), a
     * contact stiffer than K is felt as K, and the force changes by at most {@link #setForceRiseLimit} per tick.
     * {@link #useStiffContacts} sets it with the rest of the recommended configuration.
     *
     * @throws IllegalArgumentException naming the value when it is negative, infinite or NaN; nothing changes then
     */
    public void setEnergyBound(double stiffness) {
        if (!(stiffness >= 0) || !Double.isFinite(stiffness)) {
            throw new IllegalArgumentException("HapticLoop.setEnergyBound: stiffness must be a finite number >= 0 N/m"
                    + " (0 switches the bound off), got " + stiffness);
        }
        port.setEnergyBound(stiffness);
    }

    /**
     * Sets the energy bound's count reserve (sensor counts; finite, &gt;= 0; 0, the default: none), at any time: the
     * force sent is then also kept below the budget divided by this many counts of the handle's motion (the device's
     * {@link HapticDevice#positionQuantum} along the force), so that one count of the handle moving back, which the
     * energy account charges at the force held, never takes more than 1 / counts of the budget. A wall held at a small
     * force is then never emptied, and lost, by one count of encoder flicker; the price is a softer onset: the force
     * grows by at most a factor 1 + 1 / counts per count pressed in, from the seed divided by counts times a count.
     * On a device whose quantum is 0 (the Inverse3) it changes nothing.
     *
     * <p>Measured on the emulated 2DIY at 1600 N/m with {@link #useStiffContacts} (docs/haptics-stability.md, "The
     * count reserve"): at {@value #ROBUST_COUNT_RESERVE} counts no case of the adversarial suite gives the hand more
     * than 2.3 µJ and no wall with friction is lost, but the pen grip's 20 mm/s presses are felt at about 560 N/m
     * instead of 785-1220.
     *
     * @throws IllegalArgumentException naming the value when it is negative, infinite or NaN; nothing changes then
     */
    public void setEnergyBoundCountReserve(double counts) {
        if (!(counts >= 0) || !Double.isFinite(counts)) {
            throw new IllegalArgumentException("HapticLoop.setEnergyBoundCountReserve: counts must be a finite number"
                    + " >= 0 (0 switches the reserve off; HapticLoop.ROBUST_COUNT_RESERVE is the measured choice), got "
                    + counts);
        }
        port.setEnergyBoundCountReserve(counts);
    }

    /** The energy bound's count reserve (sensor counts); 0 when there is none. */
    public double energyBoundCountReserve() {
        return port.energyBoundCountReserve();
    }

    /**
     * Sets the energy bound's trim ratio r, at any time: its budget never exceeds r times the energy the force sent
     * holds in a spring of the bound's stiffness. Energy beyond that (spent on the model's dampers, or stored in a
     * contact more than r times softer than the bound) is no reserve for later: a wall stiffened under a held handle
     * then pushes with at most sqrt(r) times the force it held, and a contact softer than K / r gives back less than it
     * stored on release. 8 by default; {@link #useStiffContacts} sets 2.
     *
     * @param ratio the trim ratio (finite, &gt;= 1)
     * @throws IllegalArgumentException naming the value when it is below 1, infinite or NaN; nothing changes then
     */
    public void setEnergyBoundTrim(double ratio) {
        if (!(ratio >= 1) || !Double.isFinite(ratio)) {
            throw new IllegalArgumentException("HapticLoop.setEnergyBoundTrim: ratio must be a finite number >= 1 (8 by"
                    + " default, 2 as useStiffContacts sets it), got " + ratio);
        }
        port.setEnergyBoundTrim(ratio);
    }

    /** The energy bound's trim ratio ({@link #setEnergyBoundTrim}). */
    public double energyBoundTrim() {
        return port.energyBoundTrim();
    }

    /**
     * Switches the energy bound's hold compensation on or off, at any time. A force computed once a tick and held acts
     * about T (d + 1/2) late (T the period, d the {@linkplain #setExchangeDelay exchange delay}), which takes a damping
     * of K T (d + 1/2) from a wall of stiffness K: on a device with less damping of its own, the handle rings on a
     * stiff contact. With the compensation the bound's cap is moved along the handle's measured velocity by that
     * damping, and the ring decays as on a continuous wall; the energy account still charges every force sent. It acts
     * only where one sensor count per tick of velocity would move the force by at most 10 mN (an Inverse3, not a
     * 2DIY's encoders). Off by default; {@link #useStiffContacts} switches it on.
     */
    public void setHoldCompensation(boolean on) {
        port.setHoldCompensation(on);
    }

    /** Whether the energy bound's hold compensation is on ({@link #setHoldCompensation}). */
    public boolean isHoldCompensation() {
        return port.isHoldCompensation();
    }

    /**
     * Declares what the device itself dissipates at the handle, at any time: lower bounds of its viscous damping (N s/m;
     * finite, &gt;= 0) and of its Coulomb friction (N; finite, &gt;= 0); 0 and 0, the default, declare nothing. The
     * {@linkplain #setEnergyBound energy bound} then credits its budget with the least energy these took from the hand
     * over each measured displacement (less one sensor count per axis), as Kim and Ryu's energy bounding does. A
     * contact that has given the hand back its seed (a handle that bounced off a wall) then gets a budget again once
     * the hand moves the handle, instead of pushing with zero force until the bound is switched off. The credit is
     * safe only if the values are at most what the device really dissipates: measure the force that moves the handle
     * at a steady speed with the motors off, and declare less.
     *
     * <p>Measured on the emulated Inverse3's plant (0.5 N s/m per axis) with the bound at 3300 N/m: with 0.25 N s/m
     * declared, a pen grip's press that bounced off a stiff wall is felt at about 1000 N/m where it is otherwise lost,
     * and no case of the adversarial suite gives the hand more than 6 µJ (docs/haptics-stability.md, "On the 3-DoF
     * plant").
     *
     * @throws IllegalArgumentException naming the value when either is negative, infinite or NaN; nothing changes then
     */
    public void setDeviceDissipation(double damping, double friction) {
        if (!(damping >= 0) || !Double.isFinite(damping) || !(friction >= 0) || !Double.isFinite(friction)) {
            throw new IllegalArgumentException("HapticLoop.setDeviceDissipation: damping (N s/m) and friction (N) must be"
                    + " finite numbers >= 0, lower bounds of what the device itself dissipates (0, 0: none), got "
                    + damping + ", " + friction);
        }
        port.setDeviceDissipation(damping, friction);
    }

    /** The device's declared viscous damping at the handle (N s/m; {@link #setDeviceDissipation}). */
    public double deviceDamping() {
        return port.deviceDamping();
    }

    /** The device's declared Coulomb friction at the handle (N; {@link #setDeviceDissipation}). */
    public double deviceFriction() {
        return port.deviceFriction();
    }

    /** The count reserve (sensor counts) measured to keep every wall of the adversarial suite with friction. */
    public static final double ROBUST_COUNT_RESERVE = 1.75;

    /** The stiffness (N/m at the handle) of the energy bound; 0 when it is off. */
    public double energyBound() {
        return port.energyBound();
    }

    /**
     * Sets the largest change (N at the handle; finite, &gt; 0; default 0.5) of the force from one tick to the next,
     * as a vector (rises, falls and turns), while the {@linkplain #setEnergyBound energy bound} is on, at any time.
     * The name is older than the limit on falls.
     *
     * @throws IllegalArgumentException naming the value when it is not a finite number &gt; 0; nothing changes then
     */
    public void setForceRiseLimit(double newtons) {
        if (!(newtons > 0) || !Double.isFinite(newtons)) {
            throw new IllegalArgumentException("HapticLoop.setForceRiseLimit: limit must be a finite number > 0 N, got "
                    + newtons);
        }
        port.setForceRiseLimit(newtons);
    }

    /** The largest change (N) of the force per tick while the energy bound is on. */
    public double forceRiseLimit() {
        return port.forceRiseLimit();
    }

    /** The virtual coupling between the handle and the avatar, or null. */
    public VirtualCoupling virtualCoupling() {
        return port.coupling();
    }

    /**
     * Adds {@link FrictionCompensation} along the handle's motion (null: none, the default), at any time.
     */
    public void setFrictionCompensation(FrictionCompensation compensation) {
        port.setFriction(compensation);
    }

    /** The friction compensation in use, or null. */
    public FrictionCompensation frictionCompensation() {
        return port.friction();
    }

    /** Ticks run so far. */
    public long ticks() {
        return ticks;
    }

    /** A snapshot of the telemetry. */
    public HapticTelemetry telemetry() {
        long n = ticks;
        // read from the histograms in place: no copy of the windows (a telemetry read allocates only its result)
        return new HapticTelemetry(rateHz, n, (lastNanos - startNanos) / 1e9, missed,
                jitters.percentile(0.50), jitters.percentile(0.99), jitterMax,
                computes.percentile(0.50), computes.percentile(0.99), computeMax,
                stale, faults, spatial.limitedForces(), watchdogTrips);
    }

    /** Prints the telemetry and the scheduling to standard output. */
    public void printTelemetry() {
        System.out.println(telemetry() + ", " + scheduling);
    }

    // ------------------------------------------------------------------------------------------ the thread

    private void run() {
        long period = Math.round(1e9 / rateHz);
        long spin = spinMicros * 1000L;
        if (realtimePriority > 0) {
            // One chrt run, started while this thread is still at normal priority (a thread started from a
            // real-time thread inherits its policy, and the JDK's process reaper thread may be started here):
            // the JVM's own threads below the loop, the safety threads (the loop's watchdog, the boards' torque
            // watchdogs, which take the board's lock to zero the motors) at its priority, then this thread.
            int below = Math.max(1, realtimePriority - 1);
            Map<Pattern, Integer> others = new LinkedHashMap<>();
            if (realtimeJvmThreads) {
                others.put(RealtimeThreads.SAFEPOINT_THREADS, below);
                others.put(RealtimeThreads.COMPILER_THREADS, 1);
            }
            others.put(SAFETY_THREADS, realtimePriority);
            // the watchdog was started just after this thread and names itself as it starts: wait until Linux
            // shows its name, or the chrt run would miss it and leave it at normal priority
            RealtimeThreads.awaitThreadNamed(LOOP_WATCHDOG_NAME, WATCHDOG_NAME_WAIT_MS);
            RealtimeThreads.Grant g = RealtimeThreads.applyWithCurrentThread(others, realtimePriority,
                    deadlineScheduling ? period * DEADLINE_SHARE_PERCENT / 100 : 0, period);
            String jvm = realtimeJvmThreads ? "; VM and GC threads at " + below + ", JIT compilers at 1" : "";
            scheduling = !g.granted() ? "normal priority (real-time refused: " + g.why + ")"
                    : g.deadline ? String.format(Locale.ROOT, "real-time (SCHED_DEADLINE %d us of every %d us; safety "
                            + "threads at SCHED_FIFO %d%s)", period * DEADLINE_SHARE_PERCENT / 100_000, period / 1000,
                            realtimePriority, jvm)
                    : "real-time (SCHED_FIFO " + realtimePriority + jvm + ")";
        } else {
            scheduling = "normal priority";
        }
        try {
            beginDevice();   // so that the first tick finds a reply
        } catch (RuntimeException e) {
            fail("the first request to the board failed: " + e.getMessage());
            return;
        }
        long next = System.nanoTime() + period;
        lastTickStart = System.nanoTime();
        warmingUp = false;   // the watchdog watches from here (chrt may take tens of ms to start)
        long prevStart = 0;
        startNanos = next;
        while (running) {
            long now = System.nanoTime();
            long wait = next - now;
            if (wait > spin) {
                LockSupport.parkNanos(wait - spin);
            }
            while (System.nanoTime() - next < 0) {
                Thread.onSpinWait();
            }
            long start = System.nanoTime();
            lastTickStart = start;
            if (prevStart != 0) {
                long p = start - prevStart;
                if (p > period + period / 2) {
                    missed++;
                }
                long j = Math.abs(p - period);
                if (j > jitterMax) {
                    jitterMax = j;
                }
                jitters.record(j);
            }
            prevStart = start;
            if (!tick(period)) {
                break;
            }
            long end = System.nanoTime();
            long c = end - start;
            computes.record(c);
            if (c > computeMax) {
                computeMax = c;
            }
            lastNanos = end;
            ticks++;
            next += period;
            if (end - next > period) {
                next = end + period;   // fell behind by more than a period: do not burst to catch up
            }
        }
        running = false;
    }

    private void fail(String message) {
        failure = message;
        running = false;
        System.err.println("tactus haptic loop stopped: " + message);
    }

    private void watch() {
        long limit = watchdogMillis * 1_000_000L;
        long poll = Math.max(250_000L, limit / 4);
        boolean tripped = false;
        while (running) {
            LockSupport.parkNanos(poll);
            if (Thread.interrupted()) {
                break;
            }
            long since = System.nanoTime() - lastTickStart;
            if (!warmingUp && since > limit) {
                if (!tripped && running) {
                    tripped = true;
                    watchdogTrips++;
                    zeroOutput();
                }
            } else {
                tripped = false;
            }
        }
    }

    // ------------------------------------------------------------------------------------------ the tick

    /**
     * One tick over the {@link HapticDevice} (the 2DIY through a {@link PantographDevice}, an Inverse3, ...); returns
     * false if the loop must stop. Allocates nothing.
     */
    private boolean tick(long period) {
        boolean fresh;
        try {
            fresh = spatial.update();
        } catch (HaplyLinkException e) {
            spatial.zeroForce();
            fail(e.getMessage());
            return false;
        }
        if (fresh) {
            staleRun = 0;
            spatial.position(pos3);
            devX = pos3[0];
            devY = pos3[1];
            devZ = pos3[2];
        } else {
            stale++;
            staleRun++;
            if ((long) staleRun * period > linkTimeoutMillis * 1_000_000L) {
                spatial.close();
                fail(silenceMessage());
                return false;
            }
        }
        boolean known = !Double.isNaN(devX) && !Double.isNaN(devY) && !Double.isNaN(devZ);
        boolean poseOk = known && spatial.canRender();   // false at a pose the pantograph cannot reach
        WorkspaceMapping m = mapping;
        long steps;
        try {
            if (poseOk) {
                spatial.positionQuantum(quantum);
                port.setPositionQuantum(quantum[0], quantum[1], quantum[2]);
                if (contactPlay) {
                    port.setContactPlay(CONTACT_PLAY_COUNTS * quantum[0], CONTACT_PLAY_COUNTS * quantum[1],
                            CONTACT_PLAY_COUNTS * quantum[2]);
                } else {
                    port.setContactPlay(0, 0, 0);
                }
                port.sense(devX, devY, devZ, fresh, portTarget);
                m.toModel(portTarget, model3);
                active.setTarget(model3[0], model3[1], model3[2]);
            }
            if (mode == Mode.HAPTICS_ONLY) {
                active.step(stepsPerTick);
            }
            steps = active.takeForceCounted(force);
        } catch (RuntimeException e) {
            sendDeviceForce(0, 0, 0);
            fail("the model failed in the haptic loop, zero " + (board != null ? "torque" : "force") + " sent: " + e);
            return false;
        }
        // The avatar force is summed over the steps since the last tick: render its mean per step. In audio
        // mode the audio thread runs a buffer's steps in one burst (1024 steps every 23 ms), so most ticks see
        // no step at all and a few see hundreds: the mean of the last steps is held in between.
        if (mode == Mode.HAPTICS_ONLY) {
            double k = 1.0 / stepsPerTick;
            held3[0] = force[0] * k;
            held3[1] = force[1] * k;
            held3[2] = force[2] * k;
        } else if (steps > 0) {
            held3[0] = force[0] / steps;
            held3[1] = force[1] / steps;
            held3[2] = force[2] / steps;
        } else if (steps < 0) {
            held3[0] = force[0];             // the link cannot count its steps: render the sum, as it comes
            held3[1] = force[1];
            held3[2] = force[2];
        }                                    // steps == 0: no step ran since the last tick, keep the mean
        if (!known) {
            return sendZero();               // no position yet (start-up): nothing to render
        }
        // the force goes back along the axes the position came from (a negative scale flips them all)
        m.forceToDevice(held3, beta, force3);
        if (spatial.dimensions() == 2) {
            force3[2] = 0;
        }
        double fx = force3[0];
        double fy = force3[1];
        double fz = force3[2];
        boolean finite = Double.isFinite(fx) && Double.isFinite(fy) && Double.isFinite(fz);
        if (poseOk && finite) {
            port.command(force3);
            fx = force3[0];
            fy = force3[1];
            fz = force3[2];
        }
        if (!poseOk || !finite || !Double.isFinite(fx) || !Double.isFinite(fy) || !Double.isFinite(fz)
                || Math.sqrt(fx * fx + fy * fy + fz * fz) > forceLimit) {
            faults++;
            return sendZero();
        }
        forceX = fx;
        forceY = fy;
        forceZ = fz;
        boolean sent = sendDeviceForce(fx, fy, fz);
        port.sent(spatial.renderedShare());  // the share of the force that reached the handle (a torque clip's scale)
        return sent;
    }

    /** Sends zero force and records it as this tick's (a fault, or no position yet). */
    private boolean sendZero() {
        forceX = 0;
        forceY = 0;
        forceZ = 0;
        port.sent(0);
        return sendDeviceForce(0, 0, 0);
    }

    private String silenceMessage() {
        if (board != null) {
            return "no reply from the Haply board on " + board.device().board().describe() + " for " + linkTimeoutMillis
                    + " ms: check the USB cable and the board's power; the motors were sent zero torque";
        }
        return "no state from " + spatial.describe() + " for " + linkTimeoutMillis + " ms: check that the device is "
                + "on and connected; zero force was sent where the link still took it";
    }

    private boolean sendDeviceForce(double fx, double fy, double fz) {
        try {
            spatial.sendForce(fx, fy, fz);
            return true;
        } catch (HaplyLinkException e) {
            spatial.zeroForce();
            fail(e.getMessage());
            return false;
        }
    }

    private boolean deviceReady() {
        return spatial.isReady();
    }

    private void beginDevice() {
        spatial.begin();
    }

    private void zeroOutput() {
        spatial.zeroForce();
    }

    private void closeDevice() {
        spatial.close();
    }

    private void beforeStart(String op) {
        if (thread != null) {
            throw new IllegalStateException("HapticLoop." + op + ": configure the loop before start()");
        }
    }
}
