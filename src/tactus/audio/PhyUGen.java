package tactus.audio;

import ddf.minim.UGen;
import tactus.PhysicalModel;

/**
 * A Minim unit generator that plays a mass-interaction model: each audio sample it steps the model once
 * (or k times, with a decimation low-pass, see {@link #setOversampling(int)}), reads its listening points
 * and writes them, DC-blocked, to mono or stereo output. It patches like any UGen: into a {@code Gain},
 * effects, an {@code AudioOutput} ({@link LineOut} gives one even without a sound card) or an
 * {@code AudioRecorder}; {@link OfflineRenderer} writes it to a WAV file.
 *
 * <p>Two ways to use it:
 * <pre>
 * // the paper's way: subclass it and build the model in the constructor
 * class StringUGen extends PhyUGen {
 *   StringUGen() {
 *     super(44100);                 // creates mdl = new PhysicalModel(44100)
 *     mdl.addMass2DPlane("m1", 1, new Vect3D(0.1, 0, 0), new Vect3D());
 *     ...
 *     mdl.init();
 *     listenToMass("m4", SteppedModel.Y, 100, 0);
 *   }
 * }
 * // the direct way: wrap a model built elsewhere
 * PhyUGen ugen = new PhyUGen(model);
 * </pre>
 * A subclass may assign its own {@code mdl} in its constructor (as the paper's sketches do) and may
 * override {@link #uGenerate(float[])}; {@link #stepModel()} and {@link #mix()} are its building blocks.
 *
 * <p>{@link #sampleRateChanged()} keeps the model's rate at k times the output's. In ALGO_UNITS the
 * coefficients are per step, so a different output rate changes the pitch (as in the paper); in
 * REAL_UNITS the model keeps its physical meaning.
 *
 * <p>Threads: the audio thread steps the model. Listening points, gains, pans, the DC blocker and the
 * oversampling factor may be changed from any thread; the audio thread picks up each change whole at the
 * start of a sample. The haptic thread talks to the model only through an {@link AvatarExchange}. While it plays
 * a {@link PhysicalModel}, the PhyUGen holds the model's rate: {@code setSimRate} from the sketch is refused
 * (the rate follows the output, see {@link #sampleRateChanged()} and {@link #setOversampling(int)}).
 *
 * <p>Mistakes never reach Minim (whose output loop has no catch: one exception would silence every UGen on the
 * output for good). Nothing thrown while stepping or reading the model escapes {@link #uGenerate(float[])}: a
 * diverged model, or one whose steps throw, makes the whole output silent ({@link #isSilenced()}); a listening
 * point whose element left the model outputs 0 while the others keep sounding ({@link ListeningPoint#isSilent()});
 * an avatar that left the model gets zero force ({@link #isAvatarLost()}). Each is said once on standard error
 * (from a helper thread, not the audio thread), with how to recover, and undone as soon as the model is fixed
 * (the divergence cleared, the element added again under its name). {@link #getLastError()} keeps the cause. A
 * subclass's own {@code uGenerate} runs its own code: {@link #stepModel()} and {@link #mix()} are guarded the same
 * way, but an exception its own code throws (including a {@code DivergenceException} from a direct
 * {@code mdl.computeStep()}) still reaches Minim, since Minim's {@code tick} is final.
 */
public class PhyUGen extends UGen {
    /** Default pole of the output DC blocker: 0.95, as in the paper's sketches (corner about 343 Hz at 44.1 kHz). */
    public static final double DEFAULT_DC_COEFFICIENT = 0.95;

    /** The model, in the paper's style; a subclass builds it in its constructor. Null for a non-facade model. */
    protected PhysicalModel mdl;

    private final int nominalRate;
    private PhysicalModel boundModel;
    private SteppedModel model;
    private volatile ListeningPoint[] points = new ListeningPoint[0];
    private volatile Oversampler oversampler;
    private volatile double dcCoefficient = DEFAULT_DC_COEFFICIENT;
    private volatile boolean dcEnabled = true;
    private volatile boolean forceMono;
    private final DcBlocker dcLeft = new DcBlocker(DEFAULT_DC_COEFFICIENT);
    private final DcBlocker dcRight = new DcBlocker(DEFAULT_DC_COEFFICIENT);
    /** The attached avatar, replaced whole; null when none. */
    private volatile AvatarBinding avatarBinding;
    private final double[] target = new double[3];
    private final double[] force = new double[3];
    private double mixLeft;
    private double mixRight;
    private double mixMono;

    /** Samples between two looks for what failed (a retry of a failing step, an element added again): 46 ms at 44.1 kHz. */
    static final int RECHECK_SAMPLES = 2048;
    private final FaultState faults = new FaultState(this);
    private final RateHolder rateHolder = new RateHolder();
    // the audio thread's own fault bookkeeping
    private int sinceRecheck;
    private boolean modelSilent;
    private boolean halted;
    private boolean retryStep;
    private boolean outputSilent;
    private int haltCheck;
    /**
     * Steps between two looks for a divergence that a DivergenceListener was told of (a power of 2). Until then the
     * frozen model's positions, beyond the divergence limit, are written as 0 anyway (see finite()).
     */
    private static final int HALT_CHECK_SAMPLES = 16;
    /** The binding whose accumulator the audio thread has emptied, and the one it lost. */
    private AvatarBinding avatarStarted;
    private AvatarBinding avatarGone;
    /** The thread that computed the last sample: a new one is told to {@link AudioScheduling} (once per switch). */
    private Thread computingThread;

    /**
     * The default block length, in samples: 64, one pass through the model per 1.45 ms at 44.1 kHz, shorter than any
     * buffer Minim's outputs use (see {@link #setBlockSize(int)}).
     */
    public static final int DEFAULT_BLOCK_SIZE = 64;
    /** The longest block, in samples. */
    public static final int MAX_BLOCK_SIZE = 4096;
    private volatile int blockSize = DEFAULT_BLOCK_SIZE;
    /** Left and right buffers of at least blockSize samples, replaced whole by {@link #setBlockSize(int)}. */
    private volatile float[][] blockBuffers = new float[2][DEFAULT_BLOCK_SIZE];
    // the block the audio thread hands out: samples [blockPos, blockLength) of these are still to go
    private float[] blockLeft;
    private float[] blockRight;
    private int blockPos;
    private int blockLength;
    private boolean blockStereo;
    private int blockChannels = -1;
    private float sampleLeft;
    private float sampleRight;
    /** The listening points read a block at a time; rebuilt on the audio thread when they or the model change. */
    private BlockRecorder recorder;

    /** An avatar attached with {@link #attachAvatar(String, AvatarExchange)}: its name, handle and exchange. */
    private static final class AvatarBinding {
        final String name;
        final int handle;
        final AvatarExchange exchange;

        AvatarBinding(String name, int handle, AvatarExchange exchange) {
            this.name = name;
            this.handle = handle;
            this.exchange = exchange;
        }
    }

    /** What {@code setSimRate} names when it refuses a change: this PhyUGen, its rates and what to do instead. */
    private final class RateHolder {
        @Override
        public String toString() {
            Class<?> c = PhyUGen.this.getClass();
            String n = c == PhyUGen.class || c.getSimpleName().isEmpty() ? "PhyUGen"
                    : c.getSimpleName() + " (a PhyUGen)";
            float out = outputRate();
            int k = oversampling();
            return n + " plays this model and sets its rate to its output's rate x its oversampling ("
                    + Math.round(out) + " Hz x " + k + " = " + Math.round(out * k) + " steps/s), which a different "
                    + "model rate would detune. To change it, open the audio output at the rate you want "
                    + "(Minim.getLineOut(type, bufferSize, sampleRate)) or call setOversampling(k) on the PhyUGen";
        }
    }

    /** Decimation state for one oversampling factor, swapped in whole. */
    private static final class Oversampler {
        final int factor;
        final DecimationFilter left;
        final DecimationFilter right;

        Oversampler(int factor) {
            this.factor = factor;
            this.left = new DecimationFilter(factor);
            this.right = new DecimationFilter(factor);
        }
    }

    /**
     * The paper's way: creates {@link #mdl} as {@code new PhysicalModel(sampleRate)} (ALGO_UNITS) for the
     * subclass constructor to fill.
     *
     * @param sampleRate the audio rate the model is built for, in Hz (&gt; 0)
     */
    protected PhyUGen(int sampleRate) {
        super();
        if (sampleRate <= 0) {
            throw new IllegalArgumentException("PhyUGen: sampleRate must be > 0 Hz, got " + sampleRate);
        }
        this.nominalRate = sampleRate;
        this.mdl = new PhysicalModel(sampleRate);
        FaultReporter.ensureStarted();
    }

    /** The direct way: plays a model built elsewhere; its current rate is taken as the nominal audio rate. */
    public PhyUGen(PhysicalModel model) {
        super();
        if (model == null) {
            throw new IllegalArgumentException("PhyUGen: the model must not be null");
        }
        this.mdl = model;
        this.nominalRate = model.getSimRate();
        FaultReporter.ensureStarted();
        bind();
    }

    /** Plays any {@link SteppedModel}; {@link #mdl} stays null. */
    public PhyUGen(SteppedModel model) {
        super();
        if (model == null) {
            throw new IllegalArgumentException("PhyUGen: the model must not be null");
        }
        this.model = model;
        this.nominalRate = model.stepRate();
        FaultReporter.ensureStarted();
    }

    // ------------------------------------------------------------------ binding (never on the audio path in steady state)

    /** {@return the stepped view of the model, binding {@link #mdl} first if the subclass replaced it} */
    protected final SteppedModel steppedModel() {
        if (mdl != boundModel) {
            bind();
        }
        if (model == null) {
            throw new IllegalStateException("PhyUGen: no model; build mdl in the constructor or pass a model");
        }
        return model;
    }

    private synchronized void bind() {
        if (mdl == null || mdl == boundModel) {
            return;
        }
        SteppedModel m = new PhysicalModelStepper(mdl, rateHolder);
        for (ListeningPoint p : points) {
            p.bind(m);
        }
        AvatarBinding b = avatarBinding;
        if (b != null) {
            avatarBinding = new AvatarBinding(b.name, m.resolveAvatar(b.name), b.exchange);
        }
        model = m;
        boundModel = mdl;
    }

    /**
     * {@return the model this unit generator plays ({@link #mdl}), for the sketch's other threads: its changes are
     *     queued for the audio thread, and {@code getSnapshot()} gives positions to draw; null for a
     *     {@link SteppedModel} that is not a {@code PhysicalModel}}
     */
    public PhysicalModel getModel() {
        return mdl;
    }

    // ------------------------------------------------------------------ listening points

    /**
     * Listens to a mass's displacement along an axis, measured from where it is now.
     *
     * @param axis {@link SteppedModel#X}, {@link SteppedModel#Y} or {@link SteppedModel#Z}
     * @param gain output units per model unit
     * @param pan -1 (left) .. 1 (right)
     */
    public ListeningPoint listenToMass(String mass, int axis, double gain, double pan) {
        if (axis < 0 || axis > 2) {
            throw new IllegalArgumentException("listenToMass(\"" + mass + "\"): axis must be 0, 1 or 2, got " + axis);
        }
        return add(new ListeningPoint(ListeningPoint.Kind.MASS_DISPLACEMENT, mass, axis, gain, pan));
    }

    /** Listens to an interaction's elongation (distance minus its length parameter). */
    public ListeningPoint listenToElongation(String link, double gain, double pan) {
        return add(new ListeningPoint(ListeningPoint.Kind.LINK_ELONGATION, link, -1, gain, pan));
    }

    /** Listens to an interaction's tension, K e + Z de/dt (spring-type links, contacts, ropes and bubbles). */
    public ListeningPoint listenToTension(String link, double gain, double pan) {
        return add(new ListeningPoint(ListeningPoint.Kind.LINK_TENSION, link, -1, gain, pan));
    }

    private synchronized ListeningPoint add(ListeningPoint p) {
        SteppedModel m = steppedModel();
        java.util.concurrent.locks.Lock sampleLock = m.sampleLock();
        sampleLock.lock();
        try {
            p.bind(m);
        } finally {
            sampleLock.unlock();
        }
        ListeningPoint[] old = points;
        ListeningPoint[] next = java.util.Arrays.copyOf(old, old.length + 1);
        next[old.length] = p;
        points = next;
        return p;
    }

    /** Stops listening to a point. */
    public synchronized void removeListeningPoint(ListeningPoint p) {
        ListeningPoint[] old = points;
        for (int i = 0; i < old.length; i++) {
            if (old[i] == p) {
                ListeningPoint[] next = new ListeningPoint[old.length - 1];
                System.arraycopy(old, 0, next, 0, i);
                System.arraycopy(old, i + 1, next, i, old.length - i - 1);
                points = next;
                return;
            }
        }
        throw new IllegalArgumentException("removeListeningPoint: " + p + " is not a listening point of this PhyUGen");
    }

    /** {@return the listening points, in the order they were added} */
    public ListeningPoint[] listeningPoints() {
        return points.clone();
    }

    // ------------------------------------------------------------------ output settings

    /** Sums every point to all channels (pans ignored) when true; otherwise channel 0 is left, 1 is right. */
    public void setMono(boolean mono) {
        forceMono = mono;
    }

    /** Sets the pole of the output DC blocker (0 &le; r &lt; 1; default {@value #DEFAULT_DC_COEFFICIENT}). */
    public void setDcBlocker(double r) {
        if (!(r >= 0 && r < 1)) {
            throw new IllegalArgumentException("setDcBlocker: the coefficient must be in [0, 1), got " + r);
        }
        dcCoefficient = r;
        dcEnabled = true;
    }

    /** Turns the DC blocker on or off (on by default). */
    public void setDcBlockerEnabled(boolean enabled) {
        dcEnabled = enabled;
    }

    /** {@return the pole of the DC blocker} */
    public double dcBlockerCoefficient() {
        return dcCoefficient;
    }

    /**
     * Runs k model steps per audio sample (k = 1 turns oversampling off) and decimates them with a
     * {@link DecimationFilter}. The model's rate becomes k times the output rate. Call it while setting up:
     * it designs the filter and changes the model rate.
     */
    public synchronized void setOversampling(int k) {
        if (k < 1 || k > 16) {
            throw new IllegalArgumentException("setOversampling: k must be in 1..16, got " + k);
        }
        Oversampler next = k == 1 ? null : new Oversampler(k);
        SteppedModel m = steppedModel();
        java.util.concurrent.locks.Lock sampleLock = m.sampleLock();
        sampleLock.lock();
        try {
            oversampler = next;
            m.setStepRate(Math.round(outputRate() * k));
        } finally {
            sampleLock.unlock();
        }
    }

    /** {@return the oversampling factor k (model steps per audio sample)} */
    public int oversampling() {
        Oversampler o = oversampler;
        return o == null ? 1 : o.factor;
    }

    /**
     * Sets how many samples this PhyUGen computes in one pass through the model (1 to {@value #MAX_BLOCK_SIZE}; default
     * {@value #DEFAULT_BLOCK_SIZE}), from any thread; it takes effect at the next block. When Minim asks for the first
     * sample of a block, the model enters once and steps the whole block; the other samples come from a buffer; the
     * output is bit for bit the per-sample path's as long as nothing changes. When every listening point reads a mass
     * and neither an avatar nor oversampling is set, the block is a single call to the model
     * ({@link PhysicalModel#computeNStepsRecording}), the fastest way to play a sound model (on a 30-mass string, 133
     * ns per sample at 64 against 188 at 1). Changes to the model queued from other threads (parameters, topology),
     * and those the ticking thread makes between two samples, land at the next block boundary: at most one block
     * (1.45 ms at 64 samples and 44.1 kHz) later than with 1. No sample comes out later than with 1 as long as the
     * block is not longer than the burst in which the output asks for samples (Minim's buffer: 1,024 frames for
     * {@code getLineOut()}). The avatar exchange still runs every model step inside the block, with the haptic
     * position it finds at each step; a fault silences the rest of its block.
     *
     * <p>1 is the per-sample path: each sample enters the model on its own, and a change made between two samples
     * lands at the next one. Ask for it when something outside Minim asks for one sample at a time and reacts in
     * between: a rig that renders a few samples per haptic tick, a test that changes the model between two samples.
     *
     * @throws IllegalArgumentException naming the value when it is out of range; nothing changes then
     */
    public synchronized void setBlockSize(int samples) {
        if (samples < 1 || samples > MAX_BLOCK_SIZE) {
            throw new IllegalArgumentException("PhyUGen.setBlockSize: give 1 to " + MAX_BLOCK_SIZE + " samples (1: "
                    + "one sample per pass through the model), got " + samples);
        }
        if (blockBuffers[0].length < samples) {
            blockBuffers = new float[][] {new float[samples], new float[samples]};   // before the size that needs them
        }
        blockSize = samples;
    }

    /** {@return the number of samples computed in one pass through the model (see {@link #setBlockSize(int)})} */
    public int blockSize() {
        return blockSize;
    }

    /** {@return the group delay of the decimation filter, in audio samples (0 without oversampling)} */
    public double decimationDelaySamples() {
        Oversampler o = oversampler;
        return o == null ? 0 : o.left.delaySteps() / o.factor;
    }

    private float outputRate() {
        float sr = sampleRate();
        return sr > 0 ? sr : nominalRate;
    }

    /**
     * Couples a haptic avatar (a HapticInput3D of the model) to a haptic thread: every step the avatar's
     * target is set from the exchange's latest position and the force on the avatar is added to it.
     */
    public synchronized void attachAvatar(String avatarName, AvatarExchange exchange) {
        if (exchange == null) {
            throw new IllegalArgumentException("attachAvatar(\"" + avatarName + "\"): the exchange must not be null");
        }
        SteppedModel m = steppedModel();
        int handle = m.resolveAvatar(avatarName);
        // the audio thread empties the avatar's force accumulator before its first step with this binding
        avatarBinding = new AvatarBinding(avatarName, handle, exchange);
        faults.avatarReset();
    }

    /** Uncouples the avatar; the model keeps its last target. */
    public synchronized void detachAvatar() {
        avatarBinding = null;
        faults.avatarReset();
    }

    // ------------------------------------------------------------------ faults

    /**
     * {@return true while the whole output is silent because the model cannot step: it diverged (until
     *     {@code clearDivergence()}), or its steps throw (retried about 20 times a second)}
     */
    public boolean isSilenced() {
        return faults.isSilenced();
    }

    /**
     * {@return the last error the audio thread met (a step, a listening point, the avatar, or this PhyUGen), or null
     *     if none; kept after the PhyUGen recovers}
     */
    public Throwable getLastError() {
        return faults.lastError();
    }

    /** {@return true while the attached avatar has left the model: its exchange gets zero force until it is back} */
    public boolean isAvatarLost() {
        return faults.isAvatarLost();
    }

    /** {@return how many faults the audio thread has met (the model silenced, a point or the avatar lost, a bug)} */
    public long getFaultCount() {
        return faults.faultCount();
    }

    // ------------------------------------------------------------------ UGen

    @Override
    protected void sampleRateChanged() {
        float sr = sampleRate();
        if (sr <= 0 || (mdl == null && model == null)) {
            return;
        }
        SteppedModel m = steppedModel();
        int rate = Math.round(sr * oversampling());
        if (m.stepRate() != rate) {
            m.setStepRate(rate);
        }
    }

    /**
     * Steps the model (k times with oversampling), mixes the listening points, DC-blocks and writes them:
     * channel 0 left and 1 right in stereo, the mono mix in every channel otherwise (and in channels past 1).
     * Never throws (see the class comment): what cannot be stepped or read is written as 0.
     */
    @Override
    protected void uGenerate(float[] channels) {
        try {
            noteComputingThread();
            if (blockPos >= blockLength || channels.length != blockChannels) {
                fillBlock(blockSize, channels.length);
            }
            write(channels, blockLeft[blockPos], blockRight[blockPos], blockStereo);
            blockPos++;
        } catch (Throwable t) { // nothing may reach Minim's output loop
            faults.unexpected(t);
            blockLength = 0;
            silence(channels);
        }
    }

    /**
     * Computes n samples (stereo or mono as for this many channels) in one pass through the model: the model is
     * entered once for them; n = 1 is the per-sample path.
     */
    private void fillBlock(int n, int channelCount) {
        blockPos = 0;
        blockLength = 0;
        float[][] buffers = blockBuffers;
        blockLeft = buffers[0];
        blockRight = buffers[1];
        n = Math.min(n, blockLeft.length);
        blockChannels = channelCount;
        blockStereo = channelCount >= 2 && !forceMono;
        SteppedModel m = steppedModel();
        if (n > 1 && fillRecordedBlock(m, n)) {
            return;
        }
        m.beginSample();
        try {
            for (int i = 0; i < n; i++) {
                countTowardsRecheck(m);
                if (computeSample(m, blockStereo)) {
                    blockLeft[i] = sampleLeft;
                    blockRight[i] = sampleRight;
                } else {
                    blockLeft[i] = 0f;
                    blockRight[i] = 0f;
                    silenceFilters();
                }
                blockLength = i + 1;
            }
        } finally {
            m.endSample();
        }
    }

    /**
     * The block in one call to the model ({@link SteppedModel#stepRecording}) when nothing asks for a sample at a
     * time: no avatar (its exchange runs per step), no oversampling, and listening points that all read mass
     * displacements and can all be read. The samples are the per-sample path's, bit for bit.
     *
     * @return false when the block must take the per-sample path (nothing was stepped, or a step threw)
     */
    private boolean fillRecordedBlock(SteppedModel m, int n) {
        if (oversampler != null || avatarBinding != null || modelSilent) {
            return false;
        }
        ListeningPoint[] pts = points;
        BlockRecorder r = recorder;
        if (r == null || !r.serves(pts, m, n)) {
            r = BlockRecorder.of(pts, m, blockBuffers[0].length);   // only when the points or the model change
            recorder = r;
            if (r == null) {
                return false;
            }
        }
        if (!r.allAudible()) {
            return false;
        }
        r.beginBlock();
        int ran;
        m.beginSample();   // outside the catch, as on the per-sample path: its failure is this PhyUGen's
        try {
            ran = m.stepRecording(n, r.handles, r.axes, r.count, r.values);
        } catch (Throwable t) {
            if (!haltedAfterThrow(m)) {
                return false;   // a point's mass left, or a step threw: the per-sample path finds which
            }
            silenceModel(true, t);
            ran = 0;
        } finally {
            m.endSample();
        }
        boolean stereo = blockStereo;
        boolean dc = dcEnabled;
        double coefficient = dcCoefficient;
        dcLeft.setCoefficient(coefficient);
        dcRight.setCoefficient(coefficient);
        for (int i = 0; i < ran; i++) {
            r.mix(i);
            double left = stereo ? r.mixLeft : r.mixMono;
            double right = r.mixRight;
            if (dc) {
                left = dcLeft.process(left);
                if (stereo) {
                    right = dcRight.process(right);
                }
            }
            blockLeft[i] = finite(left);
            blockRight[i] = stereo ? finite(right) : 0f;
        }
        if (ran > 0) {
            outputSilent = false;
        }
        if (!modelSilent && m.isHalted()) {
            silenceModel(true, null);   // diverged, and a DivergenceListener was told (at the last step, too)
        }
        if (ran < n) {
            for (int i = ran; i < n; i++) {
                blockLeft[i] = 0f;
                blockRight[i] = 0f;
            }
            silenceFilters();
        }
        blockLength = n;
        // counted once done: a block that falls back to one sample per pass is counted there, sample by sample
        countTowardsRecheck(m, n);
        return true;
    }

    /** Tells {@link AudioScheduling} of a new computing thread: a field read per sample otherwise. */
    private void noteComputingThread() {
        Thread t = Thread.currentThread();
        if (t != computingThread) {
            computingThread = t;
            AudioScheduling.computingOn(t);
        }
    }

    /**
     * Steps the model for one sample (k steps with oversampling), mixes and DC-blocks it into sampleLeft and
     * sampleRight; false when the model did not step and the sample must be silent. Called inside a block.
     */
    private boolean computeSample(SteppedModel m, boolean stereo) {
        Oversampler o = oversampler;
        double left;
        double right;
        if (o == null) {
            if (!stepGuarded(m)) {
                return false;
            }
            mixPoints(m);
            left = stereo ? mixLeft : mixMono;
            right = mixRight;
        } else {
            for (int i = 0; i < o.factor; i++) {
                if (!stepGuarded(m)) {
                    return false;
                }
                mixPoints(m);
                o.left.push(stereo ? mixLeft : mixMono);
                o.right.push(mixRight);
            }
            left = o.left.output();
            right = stereo ? o.right.output() : 0;
        }
        outputSilent = false;
        if (dcEnabled) {
            double r = dcCoefficient;
            dcLeft.setCoefficient(r);
            left = dcLeft.process(left);
            if (stereo) {
                dcRight.setCoefficient(r);
                right = dcRight.process(right);
            }
        }
        sampleLeft = finite(left);
        sampleRight = stereo ? finite(right) : 0f;
        return true;
    }

    /** Writes one sample: left and right in stereo (left again in channels past 1), left everywhere in mono. */
    private static void write(float[] channels, float l, float r, boolean stereo) {
        if (stereo) {
            channels[0] = l;
            channels[1] = r;
            for (int c = 2; c < channels.length; c++) {
                channels[c] = l;
            }
        } else {
            for (int c = 0; c < channels.length; c++) {
                channels[c] = l;
            }
        }
    }

    private static float finite(double v) {
        // a diverged model must not send NaN or infinities to the sound card
        return Math.abs(v) < 1e9 ? (float) v : 0f;
    }

    /** Writes 0 to every channel; on the first silent sample, empties the filters so that nothing old rings on. */
    private void silence(float[] channels) {
        for (int c = 0; c < channels.length; c++) {
            channels[c] = 0f;
        }
        silenceFilters();
    }

    /** On the first silent sample, empties the filters so that nothing old rings on. */
    private void silenceFilters() {
        if (!outputSilent) {
            outputSilent = true;
            dcLeft.reset(0);
            dcRight.reset(0);
            Oversampler o = oversampler;
            if (o != null) {
                o.left.reset(0);
                o.right.reset(0);
            }
        }
    }

    /**
     * One model step, guarded: a diverged model is not stepped until it is cleared; a step that throws silences
     * the model until a retry (every {@link #RECHECK_SAMPLES} samples) succeeds.
     *
     * @return false when the model did not step and the output must be silent
     */
    private boolean stepGuarded(SteppedModel m) {
        if (modelSilent) {
            if (halted ? m.isHalted() : !retryStep) {
                return false;
            }
            retryStep = false;
        }
        try {
            stepOnce(m);
        } catch (Throwable t) {
            silenceModel(haltedAfterThrow(m), t);
            return false;
        }
        if ((++haltCheck & (HALT_CHECK_SAMPLES - 1)) == 0 && m.isHalted()) {
            silenceModel(true, null); // diverged, and a DivergenceListener was told
            return false;
        }
        if (modelSilent) {
            modelSilent = false;
            halted = false;
            faults.modelSoundsAgain();
        }
        return true;
    }

    /** {@return true when a model whose step just threw has diverged (false when even that question throws)} */
    private static boolean haltedAfterThrow(SteppedModel m) {
        try {
            return m.isHalted();
        } catch (Throwable ignored) {
            return false;
        }
    }

    private void silenceModel(boolean diverged, Throwable error) {
        boolean wasSilent = modelSilent;
        boolean wasHalted = halted;
        modelSilent = true;
        halted = diverged;
        if (wasSilent && wasHalted == diverged) {
            return; // a retry that failed the same way: said already
        }
        FaultNotice.Kind kind = !diverged ? FaultNotice.Kind.STEP_FAILED
                : error == null || error instanceof tactus.DivergenceException ? FaultNotice.Kind.DIVERGED
                : FaultNotice.Kind.LISTENER_THREW;
        faults.modelSilenced(kind, error);
    }

    /** Counts one sample; every {@link #RECHECK_SAMPLES} samples, {@link #recheck}s. */
    private void countTowardsRecheck(SteppedModel m) {
        countTowardsRecheck(m, 1);
    }

    /** Counts this many samples (a block, at most {@link #MAX_BLOCK_SIZE}); then as {@link #countTowardsRecheck}. */
    private void countTowardsRecheck(SteppedModel m, int samples) {
        sinceRecheck += samples;
        if (sinceRecheck >= RECHECK_SAMPLES) {
            sinceRecheck -= RECHECK_SAMPLES;   // a block that crosses the mark keeps its samples past it
            recheck(m);
        }
    }

    /** Every {@link #RECHECK_SAMPLES} samples: allows a retry of a failing step, and looks for lost elements again. */
    private void recheck(SteppedModel m) {
        if (modelSilent && !halted) {
            retryStep = true;
        }
        for (ListeningPoint p : points) {
            if (p.isSilent() && reattached(p, m)) {
                p.setSilent(false);
                faults.pointBack(p);
            }
        }
        AvatarBinding b = avatarBinding;
        if (b != null && b == avatarGone && reattached(b, m)) {
            avatarGone = null;
            avatarStarted = null; // empty its accumulator before the next step
            faults.avatarBack(b.name);
        }
    }

    private static boolean reattached(ListeningPoint p, SteppedModel m) {
        try {
            return p.reattach(m);
        } catch (Throwable t) {
            return false;
        }
    }

    private static boolean reattached(AvatarBinding b, SteppedModel m) {
        try {
            return m.reattachAvatar(b.handle);
        } catch (Throwable t) {
            return false;
        }
    }

    /** One step with the avatar exchange; only the step itself may throw (the avatar's failures are caught). */
    private void stepOnce(SteppedModel m) {
        AvatarBinding b = avatarBinding;
        if (b == null) {
            m.step();
            return;
        }
        boolean drive = b != avatarGone;
        if (drive) {
            try {
                if (b != avatarStarted) {
                    m.takeAvatarForce(b.handle, force); // start from an empty accumulator
                    avatarStarted = b;
                }
                if (b.exchange.readPosition(target)) {
                    m.setAvatarTarget(b.handle, target[0], target[1], target[2]);
                }
            } catch (Throwable t) {
                loseAvatar(b, t);
                drive = false;
            }
        }
        m.step();
        if (drive) {
            try {
                m.takeAvatarForce(b.handle, force);
            } catch (Throwable t) {
                loseAvatar(b, t);
                drive = false;
            }
        }
        if (drive) {
            b.exchange.addForce(force[0], force[1], force[2]);
        } else {
            b.exchange.addForce(0, 0, 0); // the avatar is gone: no force on the hand
        }
    }

    private void loseAvatar(AvatarBinding b, Throwable t) {
        avatarGone = b;
        faults.avatarLost(b.name, t);
    }

    /** Mixes the points that can be read; a point whose read throws goes silent (once) and adds 0. */
    private void mixPoints(SteppedModel m) {
        ListeningPoint[] pts = points;
        double l = 0;
        double r = 0;
        double mono = 0;
        for (ListeningPoint p : pts) {
            if (p.isSilent()) {
                continue;
            }
            double v;
            try {
                v = p.read(m);
            } catch (Throwable t) {
                p.setSilent(true);
                faults.pointLost(p, t);
                continue;
            }
            ListeningPoint.Gains g = p.gains();
            l += g.left * v;
            r += g.right * v;
            mono += g.gain * v;
        }
        mixLeft = l;
        mixRight = r;
        mixMono = mono;
    }

    /**
     * For subclasses that override {@link #uGenerate(float[])}: runs one model step with the avatar exchange (if
     * any), under the model's sample lock. Never throws: a model that cannot step is left as it is (see
     * {@link #isSilenced()}), and {@link #mix()} then gives 0.
     */
    protected final void stepModel() {
        try {
            noteComputingThread();
            SteppedModel m = steppedModel();
            countTowardsRecheck(m);
            m.beginSample();
            try {
                stepGuarded(m);
            } finally {
                m.endSample();
            }
        } catch (Throwable t) {
            faults.unexpected(t);
        }
    }

    /**
     * For subclasses: the mono mix of every listening point (gain applied, pan ignored) at the current step; 0
     * while the model is silenced, and 0 for a point that cannot be read. Never throws.
     */
    protected final double mix() {
        try {
            if (modelSilent) {
                return 0;
            }
            SteppedModel m = steppedModel();
            m.beginSample();
            try {
                mixPoints(m);
                double v = mixMono;
                return Math.abs(v) < 1e9 ? v : 0;
            } finally {
                m.endSample();
            }
        } catch (Throwable t) {
            faults.unexpected(t);
            return 0;
        }
    }
}
