package tactus.hapticstability;

import java.util.concurrent.locks.LockSupport;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.AvatarLink;
import tactus.haptics.Board;
import tactus.haptics.BoardModel;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.HapticLoop;
import tactus.haptics.PhysicalModelAvatar;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;
import tactus.haptics.emulator.PlantParameters;
import tactus.paramSystem;

/**
 * One touch of a virtual wall through the real haptic path: a REAL_UNITS {@link PhysicalModel} whose avatar meets a
 * wall, the real {@link HapticLoop} (calibrated units, haptics-only mode, one model step per tick), {@link Device}
 * and {@link Board} speaking the protocol to a {@link BoardEmulator} with a {@link tactus.haptics.emulator.DevicePlant}
 * and a hand.
 *
 * <p>Simulated time, deterministic: the emulator runs in lockstep (each torque write advances the plant by exactly
 * the period T), so the plant sees one write per T whatever the wall-clock timing of the loop's thread, which runs
 * at 10 kHz of wall-clock time only to finish sooner. Each tick makes exactly one write and the in-process link
 * answers each write before it returns, so the sequence of positions, forces and torques depends only on the tick
 * count. The loop's and the board's watchdogs, which would write from another thread at wall-clock times, are set
 * out of reach (60 s; off). Nothing in the loop is changed or bypassed for this.
 *
 * <p>Two walls, both along the device's y axis at the symmetric pose (x = d/2, y = 0.10 m, where the pantograph's
 * task-space mass and damping matrices are diagonal): {@link Wall#SPRING}, a two-sided spring-damper to a ground
 * 1 m away whose rest length puts the equilibrium {@code offset} below the start (a step: the linear test of the
 * theory), and {@link Wall#PLANE}, a one-sided {@code PlaneContact3D} {@code gap} below the start that the hand
 * presses into.
 */
public final class WallRig {
    /** The wall's kind. */
    public enum Wall {
        /** Two-sided spring-damper along y (bilateral): the linear case of the theory. */
        SPRING,
        /** One-sided plane contact pushing towards +y. */
        PLANE
    }

    /** What sits between the device and the model's avatar: a named wrapper of the avatar link. */
    public interface Variant {
        /** A short name for tables and plots. */
        String name();

        /** The link the loop drives: the model's own, or a wrapper around it (T: the tick period in seconds). */
        AvatarLink wrap(AvatarLink model, double period);
    }

    /** Nothing between device and avatar. */
    public static final Variant UNCONTROLLED = new Variant() {
        @Override
        public String name() {
            return "uncontrolled";
        }

        @Override
        public AvatarLink wrap(AvatarLink model, double period) {
            return model;
        }
    };

    /** The start pose's y, metres. */
    public static final double START_Y = 0.10;

    /** A run's configuration; fields are public and set before {@link #run}. */
    public static final class Config {
        /** The hardware. */
        public HaplyPreset preset = HaplyPreset.TWO_DIY_V3;
        /** The board (the M3's 12-bit PWM by default). */
        public BoardModel board = BoardModel.M3;
        /** The plant. */
        public PlantParameters plant = PlantParameters.twoDiy();
        /** Tick period, seconds (the model's rate is 1 / period, an integer). */
        public double period = 0.001;
        /** Wall stiffness, N/m. */
        public double stiffness = 100;
        /** Wall damping, N s/m. */
        public double damping = 0;
        /** The wall's kind. */
        public Wall wall = Wall.SPRING;
        /** The hand (null: {@link Hand#none()}); a script's time is the emulator's, positions in device metres. */
        public Hand hand;
        /** Ticks to run. */
        public int ticks = 2000;
        /** Encoder counts multiplied by this (1: the preset's encoders; more: a finer encoder, for the theory). */
        public float encoderScale = 1;
        /** SPRING: the equilibrium's distance below the start, metres. */
        public double offset = 0.001;
        /** PLANE: the wall's distance below the start, metres. */
        public double gap = 0.002;
        /** What sits between device and avatar. */
        public Variant variant = UNCONTROLLED;
        /** The loop thread's wall-clock rate, Hz (only how fast the run finishes; the results do not depend on it). */
        public double wallClockRate = 10_000;

        /** A copy. */
        public Config copy() {
            Config c = new Config();
            c.preset = preset;
            c.board = board;
            c.plant = plant;
            c.period = period;
            c.stiffness = stiffness;
            c.damping = damping;
            c.wall = wall;
            c.hand = hand;
            c.ticks = ticks;
            c.encoderScale = encoderScale;
            c.offset = offset;
            c.gap = gap;
            c.variant = variant;
            c.wallClockRate = wallClockRate;
            return c;
        }
    }

    /** A run's record, one sample per plant substep, positions relative to the start pose. */
    public static final class Trace {
        /** Number of samples. */
        public int n;
        /** Time, seconds. */
        public final double[] t;
        /** Handle x, y minus the start pose, metres. */
        public final double[] x;
        /** Handle y minus the start pose, metres. */
        public final double[] y;
        /** Handle velocity along y, m/s. */
        public final double[] vy;
        /** Velocity along x, m/s. */
        public final double[] vx;
        /** The hand's force on the handle, N. */
        public final double[] fx;
        /** The hand's force on the handle along y, N. */
        public final double[] fy;
        /** The loop's failure message, or null. */
        public String failure;
        /**
         * The largest change of the force sent to the device (after every controller) from one tick to the next, N:
         * a buzz that moves the handle by microns shows here rather than in the positions.
         */
        public double forceStep;
        /** The sample index of the first tick that counts (after the loop's start-up writes). */
        public int first;

        Trace(int capacity) {
            t = new double[capacity];
            x = new double[capacity];
            y = new double[capacity];
            vx = new double[capacity];
            vy = new double[capacity];
            fx = new double[capacity];
            fy = new double[capacity];
        }
    }

    private WallRig() {
    }

    /** Passes everything through and records, on the loop's thread, the largest tick-to-tick step of the force. */
    private static final class ForceSteps extends ForwardingAvatarLink {
        private final Trace trace;
        private double lastX = Double.NaN;
        private double lastY;

        ForceSteps(AvatarLink inner, Trace trace) {
            super(inner);
            this.trace = trace;
        }

        @Override
        public long takeForceCounted(double[] out) {
            long n = inner.takeForceCounted(out);
            if (!Double.isNaN(lastX)) {
                trace.forceStep = Math.max(trace.forceStep, Math.hypot(out[0] - lastX, out[1] - lastY));
            }
            lastX = out[0];
            lastY = out[1];
            return n;
        }
    }

    /** The model position of the wall surface (SPRING: the equilibrium), metres. */
    public static double wallY(Config c) {
        return c.wall == Wall.SPRING ? -c.offset : -c.gap;
    }

    /** Runs one configuration and returns its trace. */
    public static Trace run(Config c) {
        int rate = (int) Math.round(1 / c.period);
        if (Math.abs(rate * c.period - 1) > 1e-9) {
            throw new IllegalArgumentException("WallRig: 1 / period must be an integer rate, got " + c.period);
        }
        int perTick = (int) Math.round(c.period / c.plant.substep());
        BoardEmulator em = new BoardEmulator(c.preset, c.board);
        em.setLockstep(c.period);
        em.setPlant(c.plant);
        em.setHand(Hand.none());
        double x0 = c.preset.d() / 2;
        double y0 = START_Y;
        Trace tr = new Trace((c.ticks + 20) * perTick + 16);
        try (Board board = new Board(em.connect(), c.board)) {
            board.setTorqueWatchdogMillis(0);
            Device dev = new Device((byte) 5, board);
            c.preset.configure(dev);
            if (c.encoderScale != 1) {
                for (int j = 1; j <= 2; j++) {
                    dev.add_encoder(j, c.preset.encoderRotation(j), c.preset.encoderOffset(j),
                            c.preset.encoderResolution(j) * c.encoderScale, c.preset.encoderPort(j));
                }
            }
            dev.device_set_parameters();
            if (!em.place(x0, y0)) {
                throw new IllegalStateException("WallRig: the start pose is out of reach");
            }
            em.setHand(c.hand != null ? c.hand : Hand.none());
            double tStart = em.time();
            em.setProbe((t, px, py, vx, vy, hfx, hfy) -> {
                int i = tr.n;
                if (i < tr.t.length) {
                    tr.t[i] = t - tStart;
                    tr.x[i] = px - x0;
                    tr.y[i] = py - y0;
                    tr.vx[i] = vx;
                    tr.vy[i] = vy;
                    tr.fx[i] = hfx;
                    tr.fy[i] = hfy;
                    tr.n = i + 1;
                }
            });
            PhysicalModel pm = new PhysicalModel(rate, paramSystem.REAL_UNITS);
            pm.addHapticInput3D("avatar", new Vect3D(), 1);
            if (c.wall == Wall.SPRING) {
                pm.addGround3D("anchor", new Vect3D(0, -1, 0));
                pm.addSpringDamper3D("wall", 1 - c.offset, c.stiffness, c.damping, "avatar", "anchor");
            } else {
                pm.addPlaneContact("wall", 0, c.stiffness, c.damping, 1, -c.gap, "avatar");
            }
            pm.init();
            HapticLoop loop = new HapticLoop(dev, c.preset.newKinematics(),
                    new ForceSteps(c.variant.wrap(new PhysicalModelAvatar(pm, "avatar"), c.period), tr));
            loop.useRealUnits();
            loop.setOrigin(-x0, -y0, 0);
            loop.setRate(c.wallClockRate);
            loop.setWatchdogMillis(60_000);
            loop.setLinkTimeoutMillis(60_000);
            loop.start();
            long deadline = System.nanoTime() + 120_000_000_000L;
            double end = tStart + (c.ticks + 2) * c.period;
            while (loop.isRunning() && em.time() < end && System.nanoTime() < deadline) {
                LockSupport.parkNanos(1_000_000);
            }
            loop.stop();
            tr.failure = loop.failure();
            em.setProbe(null);
        }
        tr.n = Math.min(tr.n, c.ticks * perTick);
        return tr;
    }
}
