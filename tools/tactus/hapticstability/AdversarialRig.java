package tactus.hapticstability;

import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;
import java.util.function.DoubleSupplier;
import tactus.PhysicalModel;
import tactus.PlaneContact3D;
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
 * Runs one {@link AdversarialCase} through the real haptic path, with the loop configured by the configuration under
 * test, and measures it from the plant's own record: a REAL_UNITS model with the avatar and a one-sided plane wall,
 * the real {@link HapticLoop} (haptics-only, one step per tick, at the simulated rate, so that its passivity port
 * works with the true period), {@link Device} and {@link Board} speaking the protocol to a lockstep
 * {@link BoardEmulator} on the 2DIY plant, and a grasp.
 *
 * <p>Simulated time, deterministic: each torque write advances the plant by exactly one period, and the scene's
 * change of the wall or the hand is made at a fixed tick: the loop's thread waits, at that tick before the model's
 * step, while this (the sketch's) thread calls the model's public setters ({@link PhysicalModel#setLinkStiffness},
 * {@link PlaneContact3D#setPlanePosition}) or the emulator's {@link BoardEmulator#setHand}; the model queues the
 * change and applies it at that step. So a run depends only on the tick count, not on the machine's load (the loop
 * runs at the simulated rate of wall-clock time: a run takes its simulated length).
 */
public final class AdversarialRig {
    /** The start pose's y, metres (the pantograph's symmetric pose, as in {@link WallRig}). */
    static final double START_Y = WallRig.START_Y;
    /** The tick period, seconds. */
    public static final double PERIOD = 0.001;

    private AdversarialRig() {
    }

    /** What a run measured. Energies in J, forces in N, stiffness in N/m, lengths in m. */
    public static final class Result {
        /** The case. */
        public final AdversarialCase c;
        /** True if the loop did not fail and the handle was still (residual below {@link Touch#RESIDUAL_LIMIT}). */
        public boolean stable;
        /** RMS oscillation about the 20 ms moving average in the case's settled window, m. */
        public double residual;
        /** The largest energy given to the hand, max over t of -integral of F_hand . v from the reference time, J. */
        public double maxEnergyToHand;
        /** The energy given to the hand at the end of the run, J. */
        public double endEnergyToHand;
        /** The same maximum as the loop's passivity observer counts it, J. */
        public double observerMaxEnergyToHand;
        /** The largest change of the force the loop sent from one tick to the next, N. */
        public double forceStep;
        /** True if that largest change made the force larger (a rise), false if smaller (a fall, as at a release). */
        public boolean forceStepRises;
        /**
         * The stiffness the hand felt, N/m: the mean push over the mean penetration while the hand holds (the settled
         * window); NaN for taps and releases, which have no hold.
         */
        public double felt;
        /**
         * For a press, the least-squares slope of the hand's push against the penetration while it presses in, N/m
         * (the slope the sweep reads); NaN otherwise.
         */
        public double feltSlope;
        /** The loop's failure message, or null. */
        public String failure;
        /** Ticks at which the loop sent zero force for a fault (a force above its limit, 20 N by default). */
        public long faultTicks;
        /** The kinetic energy of the handle and the hand's mass at the reference time, J (counted as theirs). */
        public double storedAtReference;

        Result(AdversarialCase c) {
            this.c = c;
        }
    }

    /** The plant's record, one sample per substep (z stays 0 on the planar device). */
    static final class Record {
        int n;
        final double[] t;
        final double[] y;
        final double[] vx;
        final double[] vy;
        final double[] vz;
        final double[] fx;
        final double[] fy;
        final double[] fz;

        Record(int capacity) {
            t = new double[capacity];
            y = new double[capacity];
            vx = new double[capacity];
            vy = new double[capacity];
            vz = new double[capacity];
            fx = new double[capacity];
            fy = new double[capacity];
            fz = new double[capacity];
        }
    }

    /**
     * Watches every tick on the loop's thread: the force step and the observer's account; at the scene's event tick it
     * waits until the scene's thread has made the change.
     */
    static final class Watch extends ForwardingAvatarLink {
        final DoubleSupplier clock;
        final double tStart;
        final double eventAt;
        final double endAt;
        final double[] obsT;
        final double[] obsNet;
        final double[] f = new double[3];
        volatile HapticLoop loop;
        volatile boolean atEvent;
        volatile boolean eventDone;
        int ticks;
        double lastX = Double.NaN;
        double lastY;
        double forceStep;
        boolean forceStepRises;
        long faultTicks = -1;

        Watch(AvatarLink inner, DoubleSupplier clock, double tStart, double eventAt, double endAt, int capacity) {
            super(inner);
            this.clock = clock;
            this.tStart = tStart;
            this.eventAt = eventAt;
            this.endAt = endAt;
            obsT = new double[capacity];
            obsNet = new double[capacity];
        }

        @Override
        public void step(int n) {
            HapticLoop l = loop;
            double now = clock.getAsDouble() - tStart;
            if (l != null && now > endAt && faultTicks < 0) {
                faultTicks = l.telemetry().faultTicks;   // the run's ticks only: the loop runs on until stopped
            }
            if (l != null && now <= endAt) {
                l.deviceForce(f);
                if (!Double.isNaN(lastX)) {
                    double step = Math.hypot(f[0] - lastX, f[1] - lastY);
                    if (step > forceStep) {
                        forceStep = step;
                        forceStepRises = Math.hypot(f[0], f[1]) > Math.hypot(lastX, lastY);
                    }
                }
                lastX = f[0];
                lastY = f[1];
                if (ticks < obsT.length) {
                    obsT[ticks] = now;
                    obsNet[ticks] = l.passivity().netEnergy();
                    ticks++;
                }
            }
            if (!eventDone && now >= eventAt - 1e-9) {
                atEvent = true;
                long deadline = System.nanoTime() + 10_000_000_000L;
                while (!eventDone && System.nanoTime() < deadline) {
                    LockSupport.parkNanos(20_000);
                }
                eventDone = true;
            }
            inner.step(n);
        }
    }

    /** Runs the case with the loop configured by the configuration under test (called before the loop starts). */
    public static Result run(AdversarialCase c, Consumer<HapticLoop> configuration) {
        HaplyPreset preset = HaplyPreset.TWO_DIY_V3;
        PlantParameters plant = c.friction ? PlantParameters.twoDiy() : PlantParameters.twoDiy().withoutFriction();
        int rate = (int) Math.round(1 / PERIOD);
        int perTick = (int) Math.round(PERIOD / plant.substep());
        int ticks = (int) Math.ceil(c.duration() / PERIOD);
        BoardEmulator em = new BoardEmulator(preset, BoardModel.M3);
        em.setLockstep(PERIOD);
        em.setPlant(plant);
        em.setHand(Hand.none());
        double x0 = preset.d() / 2;
        double y0 = START_Y;
        Record rec = new Record((ticks + 20) * perTick + 16);
        Result r = new Result(c);
        Watch watch;
        try (Board board = new Board(em.connect(), BoardModel.M3)) {
            board.setTorqueWatchdogMillis(0);
            Device dev = new Device((byte) 5, board);
            preset.configure(dev);
            dev.device_set_parameters();
            if (!em.place(x0, y0)) {
                throw new IllegalStateException("AdversarialRig: the start pose is out of reach");
            }
            double tStart = em.time();
            em.setHand(Hand.grasp(c.script(x0, y0, tStart), c.grip.mass, c.grip.stiffness, c.grip.damping));
            em.setProbe((t, px, py, vx, vy, hfx, hfy) -> {
                int i = rec.n;
                if (i < rec.t.length) {
                    rec.t[i] = t - tStart;
                    rec.y[i] = py - y0;
                    rec.vx[i] = vx;
                    rec.vy[i] = vy;
                    rec.fx[i] = hfx;
                    rec.fy[i] = hfy;
                    rec.n = i + 1;
                }
            });
            PhysicalModel pm = new PhysicalModel(rate, paramSystem.REAL_UNITS);
            pm.addHapticInput3D("avatar", new Vect3D(), 1);
            PlaneContact3D wall = pm.addPlaneContact("wall", 0, c.initialStiffness(), 0, 1, -c.initialGap(), "avatar");
            pm.init();
            double eventAt = c.eventTime();
            watch = new Watch(new PhysicalModelAvatar(pm, "avatar"), em::time, tStart,
                    Double.isNaN(eventAt) ? Double.POSITIVE_INFINITY : eventAt, ticks * PERIOD, ticks + 20);
            HapticLoop loop = new HapticLoop(dev, preset.newKinematics(), watch);
            loop.useRealUnits();
            loop.setOrigin(-x0, -y0, 0);
            drive(loop, rate, configuration, watch, em::time, tStart + (ticks + 2) * PERIOD,
                    () -> change(c, pm, wall, -c.gap(), () -> em.setHand(Hand.none())), r, "AdversarialRig");
            em.setProbe(null);
        }
        rec.n = Math.min(rec.n, ticks * perTick);
        double mass = new EffectiveAxis(HaplyPreset.TWO_DIY_V3, plant, START_Y).mass + c.grip.mass;
        measure(c, rec, watch, r, mass);
        return r;
    }

    /**
     * Runs a configured scene: sets the loop's rate and generous timeouts, lets the configuration under test set the
     * rest (it may not change the rate), starts the loop, makes the scene's change on this thread (as a sketch's key
     * handler would) when the watch reaches the event's tick, stops the loop once the clock (s) reaches {@code end}
     * (or after 120 s of wall clock), and records the loop's refused ticks and failure in r.
     */
    static void drive(HapticLoop loop, int rate, Consumer<HapticLoop> configuration, Watch watch, DoubleSupplier clock,
                      double end, Runnable change, Result r, String rig) {
        loop.setRate(rate);
        loop.setWatchdogMillis(60_000);
        loop.setLinkTimeoutMillis(60_000);
        configuration.accept(loop);
        if (Math.abs(loop.rate() - rate) > 1e-9) {
            throw new IllegalArgumentException(rig + ": the configuration set the loop's rate to " + loop.rate()
                    + " Hz; the lockstep plant runs at " + rate + " Hz");
        }
        watch.loop = loop;
        loop.start();
        long deadline = System.nanoTime() + 120_000_000_000L;
        while (loop.isRunning() && clock.getAsDouble() < end && System.nanoTime() < deadline) {
            if (watch.atEvent && !watch.eventDone) {
                change.run();
                watch.eventDone = true;
            }
            LockSupport.parkNanos(200_000);
        }
        loop.stop();
        r.faultTicks = watch.faultTicks >= 0 ? watch.faultTicks : loop.telemetry().faultTicks;
        r.failure = loop.failure();
    }

    /**
     * The scene's change, through the model's public API: the wall's stiffness, or its surface moved to
     * {@code surface} (model metres along y); or the hand let go by {@code letGo}.
     */
    static void change(AdversarialCase c, PhysicalModel pm, PlaneContact3D wall, double surface, Runnable letGo) {
        switch (c.kind) {
            case SWITCH_ON:
            case STIFFEN:
                pm.setLinkStiffness("wall", c.stiffness);
                break;
            case MOVE_IN:
                wall.setPlanePosition(surface);
                break;
            case RELEASE:
                letGo.run();
                break;
            default:
                break;
        }
    }

    /**
     * Measures a run from the plant's record and the watch: energy to the hand (less the kinetic energy of this mass,
     * kg, at the reference time), the observer's figure, the force step, the residual and the felt stiffness.
     */
    static void measure(AdversarialCase c, Record rec, Watch watch, Result r, double mass) {
        int n = rec.n;
        double wallY = -c.gap();
        int firstIn = -1;
        for (int i = 0; i < n; i++) {
            if (rec.y[i] < wallY) {
                firstIn = i;
                break;
            }
        }
        double ref;
        if (c.countsFromEvent()) {
            ref = c.eventTime() - 0.05;
        } else {
            ref = firstIn < 0 ? Double.POSITIVE_INFINITY : rec.t[firstIn] - 0.05;
        }
        // the device and the hand's mass may give back the kinetic energy they had at the reference time
        double e = 0;
        double eMax = 0;
        boolean counting = false;
        for (int i = 1; i < n; i++) {
            if (rec.t[i] > ref) {
                if (!counting) {
                    counting = true;
                    r.storedAtReference = 0.5 * mass * (rec.vx[i - 1] * rec.vx[i - 1] + rec.vy[i - 1] * rec.vy[i - 1]
                            + rec.vz[i - 1] * rec.vz[i - 1]);
                    e = -r.storedAtReference;
                }
                e += -(rec.fx[i] * rec.vx[i] + rec.fy[i] * rec.vy[i] + rec.fz[i] * rec.vz[i]) * (rec.t[i] - rec.t[i - 1]);
                eMax = Math.max(eMax, e);
            }
        }
        r.maxEnergyToHand = eMax;
        r.endEnergyToHand = e;
        double netRef = Double.NaN;
        double oMax = 0;
        for (int i = 0; i < watch.ticks; i++) {
            if (watch.obsT[i] > ref) {
                if (Double.isNaN(netRef)) {
                    netRef = i > 0 ? watch.obsNet[i - 1] : 0;
                }
                oMax = Math.max(oMax, -(watch.obsNet[i] - netRef));
            }
        }
        r.observerMaxEnergyToHand = oMax;
        r.forceStep = watch.forceStep;
        r.forceStepRises = watch.forceStepRises;
        r.residual = residual(c, rec, wallY);
        r.stable = r.failure == null && r.residual < Touch.RESIDUAL_LIMIT;
        r.felt = felt(c, rec, wallY, firstIn);
        r.feltSlope = c.kind == AdversarialCase.Kind.PRESS && firstIn >= 0
                ? Touch.pressSlope(rec.t, rec.y, rec.fy, rec.n, firstIn, wallY, c.inEnd()) : Double.NaN;
    }

    /**
     * The RMS of the handle's y about its 20 ms moving average in the case's settled window, m; after a tap or a release
     * only where the handle is still in the wall (a hand that has left is not counted).
     */
    static double residual(AdversarialCase c, Record rec, double wallY) {
        int n = rec.n;
        double dt = rec.t[1] - rec.t[0];
        int w = Math.max(1, (int) Math.round(0.02 / dt));
        double[] pre = new double[n + 1];
        for (int i = 0; i < n; i++) {
            pre[i + 1] = pre[i] + rec.y[i];
        }
        double[] win = c.settledWindow();
        boolean contactOnly = c.kind == AdversarialCase.Kind.TAP || c.kind == AdversarialCase.Kind.RELEASE;
        double s = 0;
        int ns = 0;
        for (int i = 0; i < n; i++) {
            if (rec.t[i] >= win[0] && rec.t[i] <= win[1] && (!contactOnly || rec.y[i] < wallY)) {
                int lo = Math.max(0, i - w / 2);
                int hi = Math.min(n, i + w / 2 + 1);
                double d = rec.y[i] - (pre[hi] - pre[lo]) / (hi - lo);
                s += d * d;
                ns++;
            }
        }
        return ns > 0 ? Math.sqrt(s / ns) : 0;
    }

    /**
     * The felt stiffness, N/m: the mean push over the mean penetration in the settled window (the hold); NaN for taps
     * and releases.
     */
    private static double felt(AdversarialCase c, Record rec, double wallY, int firstIn) {
        if (c.kind == AdversarialCase.Kind.TAP || c.kind == AdversarialCase.Kind.RELEASE || firstIn < 0) {
            return Double.NaN;
        }
        double[] win = c.settledWindow();
        double sf = 0;
        double sp = 0;
        for (int i = 0; i < rec.n; i++) {
            if (rec.t[i] >= win[0] && rec.t[i] <= win[1]) {
                sf += -rec.fy[i];
                sp += wallY - rec.y[i];
            }
        }
        return sp > 0 ? sf / sp : Double.NaN;
    }
}
