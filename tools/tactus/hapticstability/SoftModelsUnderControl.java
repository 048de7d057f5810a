package tactus.hapticstability;

import java.util.Locale;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Function;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;
import tactus.haptics.emulator.PlantParameters;
import tactus.paramSystem;
import tactus.haptics.passivity.PassivityObserver;
import tactus.haptics.Board;
import tactus.haptics.BoardModel;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.HapticLoop;
import tactus.haptics.HapticSession;
import tactus.haptics.PhysicalModelAvatar;

/**
 * Does the passivity controller change how the paper's soft haptic examples feel? Runs the models of HeavyMassChain,
 * HapticsOnlyTemplate and RecoilString (as their sketches build them: ALGO_UNITS, the session's mapping for an
 * 800 x 600 window, their force gains) through the real {@link HapticLoop}, {@link Device} and {@link Board} on the
 * emulated 2DIY plant ({@code PlantParameters.twoDiy()}) in lockstep simulated time, with a pen grip (0.03 kg,
 * 300 N/m, 2 N s/m) that sweeps a Lissajous figure (x period 3 s; y period
 * 2 s, a 3:2 figure, or 1.5 s, a 2:1 figure through the centre) over 70 % of the workspace for 6 s from its right end, once without and once with the
 * controller (run as a {@link PortLink}, as in the stability sweep). Prints, per model, the share of ticks at which
 * the controller added damping, the energy it dissipated, and how far the handle's trajectory moved (largest and RMS
 * difference, and the largest over the sweep's amplitude). Deterministic. {@code gradle passivitySoftModels} is not
 * defined: run the class's main with the tools classpath.
 */
public final class SoftModelsUnderControl {
    private static final double T = 0.001;
    private static final double SECONDS = 6;

    /** The controller's reserve cap (J) for the runs; NaN: the controller's default. Set by main's first argument. */
    private static double reserveLimit = Double.NaN;

    private SoftModelsUnderControl() {
    }

    /** A model builder: the avatar's start (model units) in, the model out; with the sketch's force gain. */
    private static final class Example {
        final String name;
        final double beta;
        final Function<Vect3D, PhysicalModel> build;

        Example(String name, double beta, Function<Vect3D, PhysicalModel> build) {
            this.name = name;
            this.beta = beta;
            this.build = build;
        }
    }

    private static PhysicalModel heavyMassChain(Vect3D home) {
        PhysicalModel m = new PhysicalModel(1000, 60, paramSystem.ALGO_UNITS);
        m.setFriction(0.0002);
        m.addHapticInput3D("avatar", home, 10);
        for (int i = 0; i < 10; i++) {
            m.addMass3D("m" + i, 50, new Vect3D(home.x + 30 * (i + 1), home.y, 0), new Vect3D());
        }
        m.addSpringDamper3D("grip", 30, 0.002, 0.05, "avatar", "m0");
        for (int i = 0; i + 1 < 10; i++) {
            m.addSpringDamper3D("k" + i, 30, 0.002, 0.05, "m" + i, "m" + (i + 1));
        }
        m.init();
        return m;
    }

    private static PhysicalModel template(Vect3D home) {
        PhysicalModel m = new PhysicalModel(1000, 60, paramSystem.ALGO_UNITS);
        m.addHapticInput3D("avatar", home, 10);
        m.setFriction(0.0005);
        m.addGround3D("post", new Vect3D(400, 300, 0));
        m.addMass3D("ball", 20, new Vect3D(400, 300, 0), new Vect3D());
        m.addSpringDamper3D("spring", 0, 0.001, 0.02, "post", "ball");
        m.addContact3D("touch", 20, 0.05, 0.01, "avatar", "ball");
        m.init();
        return m;
    }

    private static PhysicalModel recoilString(Vect3D home) {
        PhysicalModel m = new PhysicalModel(1000, 60, paramSystem.ALGO_UNITS);
        m.setFriction(0.00005);
        double ax = 150;
        double ay = 300;
        int n = 40;
        m.addGround3D("anchor", new Vect3D(ax, ay, 0));
        for (int i = 0; i < n; i++) {
            m.addMass2DPlane("s" + i, 1, new Vect3D(ax + 9 * (i + 1), ay, 0), new Vect3D());
        }
        m.addMass2DPlane("end", 1000, new Vect3D(ax + 9 * (n + 1), ay, 0), new Vect3D());
        m.addRope3D("r0", 9, 0.05, 0.01, "anchor", "s0");
        for (int i = 0; i + 1 < n; i++) {
            m.addRope3D("r" + (i + 1), 9, 0.05, 0.01, "s" + i, "s" + (i + 1));
        }
        m.addRope3D("r" + n, 9, 0.05, 0.01, "s" + (n - 1), "end");
        m.addHapticInput3D("avatar", home, 10);
        for (int i = 0; i < n; i++) {
            m.addContact3D("pluck" + i, 10, 0.05, 0.005, "avatar", "s" + i);
        }
        m.addContact3D("shove", 24, 0.05, 0.01, "avatar", "end");
        m.init();
        return m;
    }

    /** One run's handle trajectory (x, y per tick, metres) and the observer. */
    private static final class Run {
        double[] x;
        double[] y;
        PassivityObserver observer;
        String failure;
    }

    private static Run run(Example ex, boolean control, double alpha, double[] box, double yPeriod) {
        HaplyPreset preset = HaplyPreset.TWO_DIY_V3;
        int ticks = (int) Math.round(SECONDS / T);
        BoardEmulator em = new BoardEmulator(preset, BoardModel.M3);
        em.setLockstep(T);
        em.setPlant(PlantParameters.twoDiy());
        em.setHand(Hand.none());
        double cx = 0.5 * (box[0] + box[1]);
        double cy = 0.5 * (box[2] + box[3]);
        double axp = 0.35 * (box[1] - box[0]);
        double ayp = 0.35 * (box[3] - box[2]);
        Run r = new Run();
        r.x = new double[ticks];
        r.y = new double[ticks];
        try (Board board = new Board(em.connect(), BoardModel.M3)) {
            board.setTorqueWatchdogMillis(0);
            Device dev = new Device((byte) 5, board);
            preset.configure(dev);
            dev.device_set_parameters();
            // the figure starts at its right end, away from the models' centres (the sketches start at the handle's
            // calibration pose, not inside a mass)
            if (!em.place(cx + axp, cy)) {
                throw new IllegalStateException("the start is out of reach");
            }
            em.setHand(Hand.grasp((t, out) -> {
                double u = Math.min(1, t / 0.5);   // y eases in
                out[0] = cx + axp * Math.cos(2 * Math.PI * t / 3.0);
                out[1] = cy + u * ayp * Math.sin(2 * Math.PI * t / yPeriod);
            }, 0.03, 300, 2));
            double t0 = em.time();
            em.setProbe((t, px, py, vx, vy, hfx, hfy) -> {
                int i = (int) Math.floor((t - t0) / T + 1e-9);
                if (i >= 0 && i < ticks) {
                    r.x[i] = px;
                    r.y[i] = py;
                }
            });
            // the session's mapping for an 800 x 600 window: model x = -alpha x + ox, y = alpha y + oy
            double ox = 400 + alpha * cx;
            double oy = 300 - alpha * cy;
            Vect3D home = new Vect3D(-alpha * (cx + axp) + ox, alpha * cy + oy, 0);
            PhysicalModel pm = ex.build.apply(home);
            PortLink link = new PortLink(new PhysicalModelAvatar(pm, "avatar"), T, alpha, ex.beta, true)
                    .delay(1).control(control);
            if (!Double.isNaN(reserveLimit)) {
                link.reserveLimit(reserveLimit);
            }
            HapticLoop loop = new HapticLoop(dev, preset.newKinematics(), link);
            loop.setPositionGain(alpha);
            loop.setOrigin(ox, oy, 0);
            loop.setMirrorX(true);
            loop.setForceGain(ex.beta);
            loop.setRate(10_000);
            loop.setWatchdogMillis(60_000);
            loop.setLinkTimeoutMillis(60_000);
            loop.start();
            long deadline = System.nanoTime() + 300_000_000_000L;
            double end = t0 + (ticks + 2) * T;
            while (loop.isRunning() && em.time() < end && System.nanoTime() < deadline) {
                LockSupport.parkNanos(1_000_000);
            }
            loop.stop();
            r.failure = loop.failure();
            em.setProbe(null);
            r.observer = link.observer();
        }
        return r;
    }

    /**
     * Runs the three examples with and without the controller and prints a Markdown table; args[0], if given, is the
     * controller's reserve cap in joules ("Infinity": none).
     */
    public static void main(String[] args) {
        Locale.setDefault(Locale.ROOT);
        if (args.length > 0) {
            reserveLimit = Double.parseDouble(args[0]);   // J, "Infinity" for no cap
        }
        double[] box = new double[4];
        double alpha;
        try (HapticSession s = HapticSession.openEmulated(null, HaplyPreset.TWO_DIY_V3)) {
            alpha = s.positionGain();
            s.deviceWorkspace(box);
        }
        Example[] examples = {
            new Example("HeavyMassChain", 10, SoftModelsUnderControl::heavyMassChain),
            new Example("HapticsOnlyTemplate", 1, SoftModelsUnderControl::template),
            new Example("RecoilString", 0.6, SoftModelsUnderControl::recoilString),
        };
        System.out.printf("alpha %.0f px/m, workspace x %.3f..%.3f m, y %.3f..%.3f m, %.0f s per run%n%n", alpha, box[0],
                box[1], box[2], box[3], SECONDS);
        System.out.println("| example | controller active (share of ticks) | energy in (mJ) | energy out (mJ) | dissipated by "
                + "the controller (mJ) | handle trajectory change: max (um) | RMS (um) | max / sweep amplitude |");
        System.out.println("|---|---|---|---|---|---|---|---|");
        for (double yPeriod : new double[] {2.0, 1.5}) {
            for (Example ex : examples) {
                Run off = run(ex, false, alpha, box, yPeriod);
                Run on = run(ex, true, alpha, box, yPeriod);
                double max = 0;
                double sum = 0;
                for (int i = 0; i < off.x.length; i++) {
                    double d = Math.hypot(off.x[i] - on.x[i], off.y[i] - on.y[i]);
                    max = Math.max(max, d);
                    sum += d * d;
                }
                double rms = Math.sqrt(sum / off.x.length);
                double amplitude = 0.35 * Math.min(box[1] - box[0], box[3] - box[2]);
                PassivityObserver o = on.observer;
                System.out.printf("| %s, %s figure | %.3f %% (%d of %d) | %.2f | %.2f | %.3f | %.1f | %.2f | %.2e |%s%n",
                        ex.name, yPeriod == 2.0 ? "3:2" : "2:1", 100 * o.activeShare(), o.activeTicks(), o.ticks(),
                        1000 * o.energyIn(), 1000 * o.energyOut(), 1000 * o.dissipated(), 1e6 * max, 1e6 * rms,
                        max / amplitude, off.failure != null || on.failure != null
                                ? " failure: " + off.failure + " / " + on.failure : "");
            }
        }
    }
}
