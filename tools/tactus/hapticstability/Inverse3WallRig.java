package tactus.hapticstability;

import ddf.minim.ugens.Summer;
import java.util.concurrent.locks.LockSupport;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.audio.AvatarExchange;
import tactus.audio.ExchangeAvatarLink;
import tactus.audio.PhyUGen;
import tactus.haptics.AvatarLink;
import tactus.haptics.HapticLoop;
import tactus.haptics.passivity.PassivityObserver;
import tactus.haptics.PhysicalModelAvatar;
import tactus.haptics.WorkspaceMapping;
import tactus.haptics.emulator.PlantParameters;
import tactus.haptics.emulator.SimulatedInverse3;
import tactus.paramSystem;

/**
 * One touch of a two-sided virtual wall through the real {@link HapticLoop} on the device path, with the emulated
 * Inverse3 on a 3-DoF {@link tactus.haptics.emulator.DevicePlant} in lockstep ({@link LockstepInverse3}: the
 * emulator's exchange order, d = 0), in simulated time.
 *
 * <p>The wall: a REAL_UNITS {@link PhysicalModel} whose avatar is tied by a spring-damper (K, B) to a ground 1 m away
 * along a unit direction, with a rest length that puts the equilibrium {@code offset} along it from the start (a
 * step). Along an axis it is the 1-D wall of the theory; along a diagonal the same wall seen by three axes at once.
 * The loop runs at its real rate (1 kHz of wall clock, so that its own passivity port has the right period), but
 * the device advances by exactly one period per tick on the loop's thread, so a run depends only on the tick count.
 *
 * <p>{@link Mode#HAPTICS_ONLY}: the loop steps the model (1 kHz) once per tick. {@link Mode#AUDIO}: the model runs
 * at 44.1 kHz in a {@link PhyUGen} that an {@link AvatarExchange} (SUM) ties to the loop in {@code Mode.AUDIO}, as
 * the audio-haptic examples do; the PhyUGen is rendered offline on the loop's thread after each tick's advance:
 * the audio samples that fall in that tick (44 or 45, {@code burst = 0}: an ideal audio thread that keeps pace with
 * the haptic one), or whole buffers of {@code burst} samples once that many are due (Minim's way: a 1024-sample
 * buffer every 23.2 ms).
 */
public final class Inverse3WallRig {
    /** Who steps the model. */
    public enum Mode {
        /** The haptic loop, at 1 kHz. */
        HAPTICS_ONLY,
        /** A PhyUGen at 44.1 kHz, rendered offline in step with the ticks. */
        AUDIO
    }

    /** The audio rate of {@link Mode#AUDIO}, Hz. */
    public static final int AUDIO_RATE = 44_100;

    /** A run's configuration; fields are public and set before {@link #run}. */
    public static final class Config {
        /** The plant (per axis: kg, N s/m, N). */
        public PlantParameters plant = PlantParameters.cartesian3Dof().withoutFriction();
        /** Tick period, seconds (1 / period must be an integer). */
        public double period = 0.001;
        /** Wall stiffness, N/m. */
        public double stiffness = 100;
        /** Wall damping, N s/m. */
        public double damping = 0;
        /** The wall's direction in device axes (normalised by the rig). */
        public double[] direction = {0, 1, 0};
        /** The equilibrium's distance from the start along the direction, towards the ground, metres. */
        public double offset = 0.001;
        /** Ticks to run. */
        public int ticks = 2000;
        /** The passivity controller on. */
        public boolean control;
        /** The controller's damping limit, N s/m. */
        public double dampingLimit = 10;
        /** Who steps the model. */
        public Mode mode = Mode.HAPTICS_ONLY;
        /** AUDIO: samples per buffer (0: each tick's samples right after it). */
        public int burst;

        /** A copy. */
        public Config copy() {
            Config c = new Config();
            c.plant = plant;
            c.period = period;
            c.stiffness = stiffness;
            c.damping = damping;
            c.direction = direction.clone();
            c.offset = offset;
            c.ticks = ticks;
            c.control = control;
            c.dampingLimit = dampingLimit;
            c.mode = mode;
            c.burst = burst;
            return c;
        }
    }

    /** A run's record, one sample per tick. */
    public static final class Trace {
        /** Ticks recorded. */
        public int n;
        /**
         * The handle's displacement from the start along the wall's direction, metres, at the end of each tick (the
         * equilibrium is at -offset: the ground lies behind the start).
         */
        public final double[] s;
        /** The handle's largest distance from the wall's line through the start, metres (should stay ~0). */
        public double offLine;
        /**
         * Work of the held forces on the handle up to the position the loop read at tick {@code ticks}, joules (the
         * plant's record; > 0: the device gave energy).
         */
        public double work;
        /**
         * The observer after exactly {@code ticks} ticks: energy in, out, net, dissipated by the controller (J) and its
         * active share.
         */
        public double energyIn;
        /** Energy out to the hand, J. */
        public double energyOut;
        /** Net energy in, J (>= 0: passive). */
        public double net;
        /** Energy the controller dissipated, J. */
        public double dissipated;
        /** Share of ticks the controller acted in. */
        public double activeShare;
        /** The loop's failure, or null. */
        public String failure;
        /** The offset of the run, metres. */
        public double offset;

        Trace(int capacity) {
            s = new double[capacity];
        }

        /**
         * Unstable if the handle went more than 4 offsets from the equilibrium, or if the oscillation's RMS about
         * it over the last third exceeds that over the first third.
         */
        public boolean unstable() {
            if (failure != null) {
                return true;
            }
            int third = n / 3;
            double first = 0;
            double last = 0;
            for (int i = 0; i < n; i++) {
                double e = s[i] + offset;
                if (Math.abs(e) > 4 * offset || !Double.isFinite(e)) {
                    return true;
                }
                if (i < third) {
                    first += e * e;
                } else if (i >= n - third) {
                    last += e * e;
                }
            }
            return last > first;
        }
    }

    private Inverse3WallRig() {
    }

    /** Runs one configuration and returns its trace. */
    public static Trace run(Config c) {
        int hapticRate = (int) Math.round(1 / c.period);
        if (Math.abs(hapticRate * c.period - 1) > 1e-9) {
            throw new IllegalArgumentException("Inverse3WallRig: 1 / period must be an integer rate, got " + c.period);
        }
        double norm = Math.sqrt(c.direction[0] * c.direction[0] + c.direction[1] * c.direction[1]
                + c.direction[2] * c.direction[2]);
        double[] dir = {c.direction[0] / norm, c.direction[1] / norm, c.direction[2] / norm};
        double[] start = SimulatedInverse3.HOME.clone();
        SimulatedInverse3 sim = new SimulatedInverse3();
        sim.setPlant(c.plant);
        LockstepInverse3 device = new LockstepInverse3(sim, c.period);
        Trace tr = new Trace(c.ticks);
        tr.offset = c.offset;

        PhysicalModel pm = new PhysicalModel(c.mode == Mode.AUDIO ? AUDIO_RATE : hapticRate, paramSystem.REAL_UNITS);
        pm.addHapticInput3D("avatar", new Vect3D(start[0], start[1], start[2]), 1);
        pm.addGround3D("anchor", new Vect3D(start[0] - dir[0], start[1] - dir[1], start[2] - dir[2]));
        pm.addSpringDamper3D("wall", 1 - c.offset, c.stiffness, c.damping, "avatar", "anchor");
        pm.init();

        AvatarLink link;
        AudioSide audio = null;
        if (c.mode == Mode.AUDIO) {
            PhyUGen ugen = new PhyUGen(pm);
            AvatarExchange exchange = new AvatarExchange(AvatarExchange.ForceMode.SUM);
            ugen.attachAvatar("avatar", exchange);
            audio = new AudioSide(ugen, hapticRate, c.burst);
            link = new ExchangeAvatarLink(exchange);
        } else {
            link = new PhysicalModelAvatar(pm, "avatar");
        }
        AudioSide a = audio;
        HapticLoop loop = new HapticLoop(device, link);
        device.setListener((tick, p, f) -> {
            if (tick == c.ticks) {
                // the energies after exactly c.ticks ticks (the loop runs on until the rig's thread stops it)
                PassivityObserver o = loop.passivity();
                tr.work = device.workSeen();
                tr.energyIn = o.energyIn();
                tr.energyOut = o.energyOut();
                tr.net = o.netEnergy();
                tr.dissipated = o.dissipated();
                tr.activeShare = o.activeShare();
            }
            if (a != null) {
                a.afterTick(tick);
            }
            if (tick == 0) {
                return;   // the loop's first request, before its first tick
            }
            int i = (int) (tick - 1);
            if (i < tr.s.length) {
                double dx = p[0] - start[0];
                double dy = p[1] - start[1];
                double dz = p[2] - start[2];
                double along = dx * dir[0] + dy * dir[1] + dz * dir[2];
                tr.s[i] = along;   // the equilibrium is at -offset
                double ox = dx - along * dir[0];
                double oy = dy - along * dir[1];
                double oz = dz - along * dir[2];
                tr.offLine = Math.max(tr.offLine, Math.sqrt(ox * ox + oy * oy + oz * oz));
                tr.n = i + 1;
            }
        });

        loop.setWorkspaceMapping(WorkspaceMapping.identity());
        loop.setForceGain(1);
        loop.setMode(c.mode == Mode.AUDIO ? HapticLoop.Mode.AUDIO : HapticLoop.Mode.HAPTICS_ONLY);
        loop.setRate(hapticRate);
        loop.setWatchdogMillis(60_000);
        loop.setLinkTimeoutMillis(60_000);
        loop.setHeapWarmup(false);
        loop.setPassivityDampingLimit(c.dampingLimit);
        loop.setExchangeDelay(0);
        loop.setPassivityControl(c.control);
        loop.start();
        long deadline = System.nanoTime() + 120_000_000_000L;
        while (loop.isRunning() && device.ticks() <= c.ticks && System.nanoTime() < deadline) {
            LockSupport.parkNanos(2_000_000);
        }
        loop.stop();
        tr.failure = loop.failure();
        if (tr.failure == null && device.ticks() <= c.ticks) {
            tr.failure = "the run did not finish in 120 s of wall clock (" + device.ticks() + " ticks)";
        }
        loop.close();
        return tr;
    }

    /** The PhyUGen rendered offline on the loop's thread, in step with the ticks. */
    private static final class AudioSide {
        private final Summer root = new Summer();
        private final float[] frame = new float[1];
        private final int hapticRate;
        private final int burst;
        private long rendered;
        private long due;

        AudioSide(PhyUGen ugen, int hapticRate, int burst) {
            this.hapticRate = hapticRate;
            this.burst = burst;
            if (burst <= 0) {
                ugen.setBlockSize(1);   // a few samples per tick, the haptic position changing in between
            }
            ugen.patch(root);
            ugen.setSampleRate(AUDIO_RATE);
            ugen.setChannelCount(1);
            root.setSampleRate(AUDIO_RATE);
            root.setChannelCount(1);
        }

        /** After tick k's advance: the samples that fall in it (or whole buffers once due). */
        void afterTick(long tick) {
            due = (tick + 1) * AUDIO_RATE / hapticRate;
            if (burst <= 0) {
                render(due - rendered);
            } else {
                while (due - rendered >= burst) {
                    render(burst);
                }
            }
        }

        private void render(long samples) {
            for (long i = 0; i < samples; i++) {
                frame[0] = 0;
                root.tick(frame);
            }
            rendered += samples;
        }
    }
}
