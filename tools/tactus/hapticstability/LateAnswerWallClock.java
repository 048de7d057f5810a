package tactus.hapticstability;

import java.util.List;
import java.util.Locale;
import java.util.concurrent.locks.LockSupport;

import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.HapticLoop;
import tactus.haptics.passivity.PassivityObserver;
import tactus.haptics.PhysicalModelAvatar;
import tactus.haptics.WorkspaceMapping;
import tactus.haptics.emulator.Hand3D;
import tactus.haptics.emulator.InverseServiceEmulator;
import tactus.haptics.emulator.PlantParameters;
import tactus.haptics.emulator.SimulatedInverse3;
import tactus.haptics.inverse.Inverse3Device;
import tactus.paramSystem;

/**
 * StiffWall3D's case on the wall-clock path: the haptic loop, {@link Inverse3Device}, the WebSocket and the
 * {@link InverseServiceEmulator} advancing by the real time between messages (as the example runs it), the generic
 * 3-DoF plant, a hand (a spring of 300 N/m and 3 N s/m, as {@code HapticSession3D}'s) pressing slowly in and out of a
 * one-sided 3000 N/m wall, the passivity controller on (limit 100 N s/m unless told). Runs alternate the fixed-delay account
 * (late-answer bound 0, as before) and the late-answer bound of {@code Inverse3Device} (4), and print per run the
 * observer's net energy and the true net energy into the model from the emulator's record of each force and the
 * handle's displacement over the period it was applied. Wall-clock: the figures depend on the machine's load.
 *
 * <p>Usage: {@code LateAnswerWallClock [seconds per run, default 5] [runs per setting, default 3] [press period, s, default 1.5] [damping limit, N s/m, default 100] [bounds, default 0,4]}.
 */
public final class LateAnswerWallClock {
    private static final double K = 3000;
    private static final double WALL_BELOW = 0.02;   // m: the wall's plane, below the home position along x

    private LateAnswerWallClock() {
    }

    /** One run; returns {observer net, true net, dissipated, active share, forces} (J, J, J, 0..1, count). */
    static double[] run(int lateBound, double seconds, double pressPeriod, double dampingLimit) throws Exception {
        SimulatedInverse3 sim = new SimulatedInverse3();
        sim.setPlant(PlantParameters.cartesian3Dof());
        double[] home = SimulatedInverse3.HOME;
        double wall = home[0] - WALL_BELOW;
        // the hand's target: 8 mm outside the wall to 12 mm into it and back, once a press period
        sim.setHand(Hand3D.followingScript((t, out) -> {
            out[0] = wall - 0.002 + 0.010 * Math.cos(2 * Math.PI * t / pressPeriod);
            out[1] = home[1];
            out[2] = home[2];
        }, 300, 3));
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0, sim)) {
            emu.setRecording(true);
            Inverse3Device device = Inverse3Device.open(emu.uri(), 5000);
            PhysicalModel pm = new PhysicalModel(1000, paramSystem.REAL_UNITS);
            pm.addHapticInput3D("avatar", new Vect3D(home[0], home[1], home[2]), 1);
            pm.addPlaneContact("wall", 0, K, 0, 0, wall, "avatar");
            pm.init();
            HapticLoop loop = new HapticLoop(device, new PhysicalModelAvatar(pm, "avatar"));
            loop.setWorkspaceMapping(WorkspaceMapping.identity());
            loop.setForceGain(1);
            loop.setHeapWarmup(false);
            loop.setPassivityDampingLimit(dampingLimit);
            loop.setPassivityControl(true);
            loop.setLateAnswerBound(lateBound);
            loop.start();
            long end = System.nanoTime() + (long) (seconds * 1e9);
            while (loop.isRunning() && System.nanoTime() < end) {
                LockSupport.parkNanos(5_000_000);
            }
            PassivityObserver o = loop.passivity();
            double observed = o.netEnergy();
            double dissipated = o.dissipated();
            double active = o.activeShare();
            loop.stop();
            if (loop.failure() != null) {
                throw new IllegalStateException("the loop failed: " + loop.failure());
            }
            loop.close();
            // frame 0 is the snapshot on connect, frame m answers message m; message 1 is the handshake, so force i
            // (from 0) is message i + 2 and acted over the advance from frame i + 1 to frame i + 2
            List<double[]> frames = emu.sentPositions();
            List<double[]> forces = emu.receivedForces();
            double into = 0;
            for (int i = 0; i + 2 < frames.size() && i < forces.size(); i++) {
                double[] f = forces.get(i);
                double[] a = frames.get(i + 1);
                double[] b = frames.get(i + 2);
                into -= f[0] * (b[0] - a[0]) + f[1] * (b[1] - a[1]) + f[2] * (b[2] - a[2]);
            }
            return new double[] {observed, into, dissipated, active, forces.size()};
        }
    }

    /** Prints the runs. */
    public static void main(String[] args) throws Exception {
        double seconds = args.length > 0 ? Double.parseDouble(args[0]) : 5;
        int runs = args.length > 1 ? Integer.parseInt(args[1]) : 3;
        double press = args.length > 2 ? Double.parseDouble(args[2]) : 1.5;
        double limit = args.length > 3 ? Double.parseDouble(args[3]) : 100;
        String[] which = (args.length > 4 ? args[4] : "0," + Inverse3Device.LATE_ANSWER_BOUND).split(",");
        int[] bounds = new int[which.length];
        for (int i = 0; i < which.length; i++) {
            bounds[i] = Integer.parseInt(which[i].trim());
        }
        System.out.println("StiffWall3D case, wall clock, 3000 N/m, controller on (limit " + limit + " N s/m), " + seconds + " s a run, a press every " + press + " s");
        System.out.println("| late bound | observer net (mJ) | true net (mJ) | dissipated (mJ) | active | forces |");
        System.out.println("|---|---|---|---|---|---|");
        for (int r = 0; r < runs; r++) {
            for (int bound : bounds) {
                double[] x = run(bound, seconds, press, limit);
                System.out.println(String.format(Locale.ROOT, "| %d | %.1f | %.1f | %.1f | %.0f %% | %d |", bound,
                        1e3 * x[0], 1e3 * x[1], 1e3 * x[2], 100 * x[3], (long) x[4]));
            }
        }
    }
}
