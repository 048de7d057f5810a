package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;
import tactus.haptics.pantograph.PantographKinematics;
import tactus.haptics.transport.Transport;
import tactus.haptics.transport.WireFormat;

/** The haptic loop through the emulator: inertia of the paper's heavy mass chain, safety, telemetry. */
class HapticLoopTest {

    /** Rest, then constant acceleration along device +x: x(t) = x0 + a (t - t1)^2 / 2 after t1. */
    private static final double REST = 0.3;
    private static final double ACCEL = 0.1;   // m/s^2

    private static final class Rig implements AutoCloseable {
        final BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        final RecordingTransport link = new RecordingTransport(emulator.connect());
        final Board board = new Board(link);
        final Device device = new Device((byte) 3, board);
        final double x0;
        final double y0 = 0.08;

        Rig(boolean moving) {
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            x0 = 0.0;
            emulator.setHand(Hand.scripted((t, out) -> {
                double u = Math.max(0, t - REST);
                out[0] = x0 + (moving ? 0.5 * ACCEL * u * u : 0);
                out[1] = y0;
            }));
        }

        HapticLoop loop(AvatarLink avatar) {
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), avatar);
            loop.setOrigin(0, -200 * y0, 0);   // the start pose maps to the model origin
            return loop;
        }

        @Override
        public void close() {
            board.close();
        }
    }

    /** The paper's HeavyMassChain: an avatar, 10 masses (mass m), 9 spring-dampers l0 0.1, K 0.003, Z 0.05. */
    private static PhysicalModel chain(double mass) {
        PhysicalModel pm = new PhysicalModel(1000);
        pm.addHapticInput3D("hapticMass", new Vect3D(), 10);
        for (int i = 0; i < 10; i++) {
            pm.addMass3D("m" + i, mass, new Vect3D(0.1 * (i + 1), 0, 0), new Vect3D());
        }
        for (int i = 0; i < 9; i++) {
            pm.addSpringDamper3D("k" + i, 0.1, 0.003, 0.05, "m" + i, "m" + (i + 1));
        }
        pm.addSpringDamper3D("grip", 0.1, 0.003, 0.05, "hapticMass", "m0");
        pm.init();
        return pm;
    }

    /** Runs the drag for the given chain mass; returns {mean Fx at rest, mean Fx while accelerating}. */
    private static double[] drag(double mass) {
        try (Rig rig = new Rig(true)) {
            HapticLoop loop = rig.loop(new PhysicalModelAvatar(chain(mass), "hapticMass"));
            loop.start();
            double restSum = 0;
            int restN = 0;
            double accSum = 0;
            int accN = 0;
            double[] f = new double[2];
            double t;
            while ((t = rig.emulator.time()) < REST + 0.6) {
                LockSupport.parkNanos(1_000_000);
                loop.deviceForce(f);
                if (t > 0.05 && t < REST) {
                    restSum += f[0];
                    restN++;
                } else if (t > REST + 0.1) {
                    accSum += f[0];
                    accN++;
                }
                assertTrue(loop.isRunning(), () -> "loop stopped: " + loop.failure());
            }
            loop.close();
            assertTrue(restN > 0 && accN > 0);
            assertEquals(0, loop.telemetry().faultTicks);
            return new double[] {restSum / restN, accSum / accN};
        }
    }

    @Test
    void draggingTheHeavyMassChainFeelsItsInertia() {
        double[] heavy = drag(50);
        double[] light = drag(0.5);
        // accelerating along +x, the chain lags and the grip pulls back: the force opposes the acceleration
        assertTrue(heavy[1] < 0, "force while accelerating along +x: " + heavy[1]);
        // at rest there is nothing to feel
        assertTrue(Math.abs(heavy[0]) < 0.05 * Math.abs(heavy[1]), "rest " + heavy[0] + " vs drag " + heavy[1]);
        // and it is inertia: a chain 100 times lighter pulls back far less
        assertTrue(Math.abs(heavy[1]) > 5 * Math.abs(light[1]), "heavy " + heavy[1] + " vs light " + light[1]);
    }

    /**
     * An avatar with a constant force that turns bad at a chosen tick. It notes, for each tick, how many writes
     * the link had seen: the tick's own write is the next one (a watchdog write may come between ticks).
     */
    private static final class FaultyAvatar implements AvatarLink {
        final int badTick;
        final double badValue;
        final boolean throwInstead;
        final int[] writeOfTick = new int[100_000];
        RecordingTransport link;
        volatile int ticks;

        FaultyAvatar(int badTick, double badValue, boolean throwInstead) {
            this.badTick = badTick;
            this.badValue = badValue;
            this.throwInstead = throwInstead;
        }

        float[] torquesOfTick(int k) {
            synchronized (link) {
                return torquesOf(link.writes.get(writeOfTick[k]));
            }
        }

        @Override
        public void setTarget(double x, double y, double z) {
        }

        @Override
        public void takeForce(double[] out) {
            if (link != null && ticks < writeOfTick.length) {
                synchronized (link) {
                    writeOfTick[ticks] = link.writes.size();
                }
            }
            boolean bad = ticks >= badTick;
            out[0] = bad ? badValue : 0.002;   // beta 100: 0.2 N
            out[1] = bad ? badValue : -0.003;
            out[2] = 0;
            ticks++;
        }

        @Override
        public void step(int n) {
            if (throwInstead && ticks >= badTick) {
                throw new IllegalStateException("diverged on purpose");
            }
        }
    }

    private static float[] torquesOf(byte[] write) {
        return new float[] {WireFormat.getFloat(write, 2), WireFormat.getFloat(write, 6)};
    }


    private static void runUntil(HapticLoop loop, FaultyAvatar a, int ticks) {
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (a.ticks < ticks && loop.isRunning() && System.nanoTime() < deadline) {
            LockSupport.parkNanos(1_000_000);
        }
    }

    @Test
    void nonFiniteOrRunawayForceGivesZeroTorqueInTheSameTick() {
        for (double bad : new double[] {Double.NaN, Double.POSITIVE_INFINITY, 1e6}) {
            try (Rig rig = new Rig(false)) {
                FaultyAvatar a = new FaultyAvatar(50, bad, false);
                a.link = rig.link;
                HapticLoop loop = rig.loop(a);
                loop.start();
                runUntil(loop, a, 81);
                loop.stop();
                float[] before = a.torquesOfTick(49);
                assertTrue(before[0] != 0 || before[1] != 0, "torque before the fault");
                for (int k = 50; k < 80; k++) {
                    float[] t = a.torquesOfTick(k);
                    assertEquals(0f, t[0], "tick " + k + " with force " + bad);
                    assertEquals(0f, t[1], "tick " + k + " with force " + bad);
                }
                assertTrue(loop.telemetry().faultTicks >= 30);
            }
        }
    }

    @Test
    void aDivergingModelGivesZeroTorqueWithinOneTick() {
        // a real model that blows up: a mass on a spring far above the explicit scheme's stability limit
        PhysicalModel pm = new PhysicalModel(1000);
        pm.addHapticInput3D("hapticMass", new Vect3D(), 1);
        pm.addMass3D("m", 1, new Vect3D(0.1, 0, 0), new Vect3D());
        pm.addSpringDamper3D("grip", 0, 5, 0, "hapticMass", "m");
        pm.addGround3D("g", new Vect3D(0.1, 0, 0));
        pm.addSpringDamper3D("wall", 0, 5, 0, "m", "g");
        try {
            pm.setStabilityPolicy(tactus.StabilityPolicy.WARN);
        } catch (RuntimeException ignored) {
            // the default policy is used
        }
        java.io.PrintStream err = System.err;
        try {
            System.setErr(new java.io.PrintStream(new java.io.ByteArrayOutputStream()));
            pm.init();
        } finally {
            System.setErr(err);
        }
        PhysicalModelAvatar inner = new PhysicalModelAvatar(pm, "hapticMass");
        double[][] seen = new double[4000][];
        int[] writeOfTick = new int[4000];
        int[] n = {0};
        RecordingTransport[] link = new RecordingTransport[1];
        AvatarLink logged = new AvatarLink() {
            @Override
            public void setTarget(double x, double y, double z) {
                inner.setTarget(x, y, z);
            }

            @Override
            public void takeForce(double[] out) {
                inner.takeForce(out);
                if (n[0] < seen.length) {
                    seen[n[0]] = out.clone();
                    synchronized (link[0]) {
                        writeOfTick[n[0]] = link[0].writes.size();
                    }
                }
                n[0]++;
            }

            @Override
            public void step(int k) {
                inner.step(k);
            }
        };
        try (Rig rig = new Rig(false)) {
            link[0] = rig.link;
            HapticLoop loop = rig.loop(logged);
            loop.setForceGain(1e-3);
            loop.start();
            long deadline = System.nanoTime() + 5_000_000_000L;
            while (loop.isRunning() && n[0] < 400 && System.nanoTime() < deadline) {
                LockSupport.parkNanos(1_000_000);
            }
            loop.stop();
            List<byte[]> w;
            synchronized (rig.link) {
                w = new java.util.ArrayList<>(rig.link.writes);
            }
            int checked = 0;
            boolean sawFault = false;
            for (int k = 0; k < Math.min(n[0], seen.length); k++) {
                double[] f = seen[k];
                if (f == null) {
                    continue;
                }
                double fx = -1e-3 * f[0];
                double fy = 1e-3 * f[1];
                boolean bad = !Double.isFinite(fx) || !Double.isFinite(fy) || Math.hypot(fx, fy) > 20;
                if (bad && writeOfTick[k] < w.size()) {
                    sawFault = true;
                    float[] t = torquesOf(w.get(writeOfTick[k]));
                    assertEquals(0f, t[0], "tick " + k);
                    assertEquals(0f, t[1], "tick " + k);
                    checked++;
                }
            }
            assertTrue(sawFault || loop.failure() != null, "the model did diverge (forces or an exception)");
            if (loop.failure() != null) {
                float[] last = torquesOf(rig.link.last());
                assertEquals(0f, last[0]);
                assertEquals(0f, last[1]);
            } else {
                assertTrue(checked > 0);
            }
        }
    }

    @Test
    void aModelThatThrowsStopsTheLoopAfterZeroTorque() {
        try (Rig rig = new Rig(false)) {
            FaultyAvatar a = new FaultyAvatar(30, 0, true);
            HapticLoop loop = rig.loop(a);
            loop.start();
            assertStoppedOnDivergenceWithZeroTorque(rig, loop, 5);
        }
    }

    @Test
    void torqueIsScaledDownToTheLimitKeepingItsDirection() {
        try (Rig rig = new Rig(false)) {
            FaultyAvatar a = new FaultyAvatar(Integer.MAX_VALUE, 0, false);
            a.link = rig.link;
            HapticLoop loop = rig.loop(a);
            loop.setForceGain(1e4);          // 20 N and 30 N: over the torque limit, under the runaway limit 50 N
            loop.setForceLimit(50);
            loop.setTorqueLimit(0.05);
            loop.start();
            runUntil(loop, a, 30);
            loop.stop();
            float[] t = a.torquesOfTick(20);
            assertEquals(0.05f, Math.max(Math.abs(t[0]), Math.abs(t[1])), 1e-6f);
            PantographKinematics k = HaplyPreset.HAPLY_2018.newKinematics();
            double[] th = new double[2];
            assertTrue(k.inverse(rig.x0, rig.y0, th));
            k.forward(th[0], th[1]);
            double[] full = new double[2];
            k.torques(-1e4 * 0.002, 1e4 * -0.003, 1.0, full);
            assertEquals(full[0] / full[1], t[0] / t[1], 2e-2 * Math.abs(full[0] / full[1]), "same direction");
            assertTrue(loop.telemetry().clampedTicks > 0);
        }
    }

    @Test
    void watchdogZeroesTheTorqueWhenTicksStall() {
        try (Rig rig = new Rig(false)) {
            AvatarLink stalling = new AvatarLink() {
                int ticks;

                @Override
                public void setTarget(double x, double y, double z) {
                }

                @Override
                public void takeForce(double[] out) {
                    out[0] = 0.002;
                    out[1] = -0.003;
                    out[2] = 0;
                }

                @Override
                public void step(int n) {
                    if (++ticks == 50) {
                        LockSupport.parkNanos(500_000_000L);   // the model hangs for 500 ms
                    }
                }
            };
            HapticLoop loop = rig.loop(stalling);
            loop.setWatchdogMillis(20);
            loop.start();
            long deadline = System.nanoTime() + 5_000_000_000L;
            while (loop.ticks() < 49 && System.nanoTime() < deadline) {
                LockSupport.parkNanos(1_000_000);
            }
            LockSupport.parkNanos(150_000_000L);   // inside the stall (the watchdog acts after 20 ms)
            assertEquals(0, rig.emulator.duty(1), "the watchdog zeroed the motors");
            assertEquals(0, rig.emulator.duty(2));
            assertTrue(loop.telemetry().watchdogTrips >= 1);
            loop.stop();
        }
    }

    @Test
    void lostLinkStopsTheLoopWithAClearMessage() {
        try (Rig rig = new Rig(false)) {
            FaultyAvatar a = new FaultyAvatar(Integer.MAX_VALUE, 0, false);
            HapticLoop loop = rig.loop(a);
            loop.start();
            runUntil(loop, a, 50);
            rig.emulator.unplug();
            awaitStop(loop, 5);
            assertNotNull(loop.failure());
            assertTrue(loop.failure().contains("unplugged") && loop.failure().contains("USB"), loop.failure());
            loop.close();   // no throw
        }
    }

    @Test
    void silentBoardStopsTheLoopAfterTheLinkTimeout() {
        try (Rig rig = new Rig(false)) {
            FaultyAvatar a = new FaultyAvatar(Integer.MAX_VALUE, 0, false);
            HapticLoop loop = rig.loop(a);
            loop.setLinkTimeoutMillis(30);
            loop.start();
            runUntil(loop, a, 20);
            rig.emulator.dropReplies(Integer.MAX_VALUE);
            awaitStop(loop, 5);
            assertTrue(loop.failure().contains("no reply"), loop.failure());
            assertEquals(0, rig.emulator.duty(1), "zero torque was sent before closing");
            assertTrue(rig.board.isClosed());
        }
    }

    @Test
    void telemetryIsConsistent() {
        try (Rig rig = new Rig(false)) {
            FaultyAvatar a = new FaultyAvatar(Integer.MAX_VALUE, 0, false);
            HapticLoop loop = rig.loop(a);
            loop.setRate(500);
            loop.start();
            runUntil(loop, a, 100);
            loop.stop();
            HapticTelemetry t = loop.telemetry();
            assertTrue(t.ticks >= 100);
            assertEquals(500, t.nominalHz);
            assertTrue(t.achievedHz > 0);
            assertTrue(t.jitterP50Us <= t.jitterP99Us && t.jitterP99Us <= t.jitterMaxUs + 1e-9);
            assertTrue(t.computeP50Us <= t.computeP99Us && t.computeP99Us <= t.computeMaxUs + 1e-9);
            assertTrue(t.missedSteps <= t.ticks);
            assertTrue(t.toString().contains("missed"));
        }
    }

    @Test
    void strayAndForeignFramesDuringTheLoopAreCountedAndSurvived() {
        try (Rig rig = new Rig(false)) {
            FaultyAvatar a = new FaultyAvatar(Integer.MAX_VALUE, 0, false);
            HapticLoop loop = rig.loop(a);
            loop.start();
            runUntil(loop, a, 50);
            byte[] foreign = new byte[9];
            foreign[0] = 9;
            double[] p = new double[2];
            double worst = 0;
            for (int i = 0; i < 10; i++) {
                byte[][] faults = {{0x42}, foreign, {3, 1, 2}};   // a stray byte, another device's frame, a partial one
                for (byte[] f : faults) {
                    rig.emulator.injectToHost(f);
                    for (int ms = 0; ms < 3; ms++) {
                        LockSupport.parkNanos(1_000_000);
                        loop.devicePosition(p);
                        worst = Math.max(worst, Math.hypot(p[0] - rig.x0, p[1] - rig.y0));
                    }
                }
            }
            assertTrue(worst < 1e-3, "no garbage position was ever used: off by " + worst + " m");
            int before = a.ticks;
            runUntil(loop, a, before + 50);
            assertTrue(loop.isRunning(), () -> "the loop survives: " + loop.failure());
            assertTrue(rig.board.idMismatches() + rig.board.unexpectedBytes() + rig.board.timeouts() > 0, "counted");
            assertTrue(rig.board.framesRead() > 100);
            loop.devicePosition(p);
            assertEquals(rig.x0, p[0], 1e-3, "the position is still the handle's");
            assertEquals(rig.y0, p[1], 1e-3);
            loop.stop();
        }
    }

    @Test
    void calibratedModeRendersAOneGramWeightAsNineMilliNewtons() {
        // REAL_UNITS: a 1 g mass hanging from the avatar on a spring, gravity 9.81 m/s^2 pulling towards -y
        PhysicalModel pm = new PhysicalModel(1000, tactus.paramSystem.REAL_UNITS);
        pm.addHapticInput3D("hapticMass", new Vect3D(), 1);
        pm.addMass3D("bob", 0.001, new Vect3D(0, -0.05 - 0.001 * 9.81 / 10, 0), new Vect3D());
        pm.addSpringDamper3D("cord", 0.05, 10, 0.1, "hapticMass", "bob");
        pm.setGravityDirection(new Vect3D(0, 1, 0));
        pm.setGravity(9.81);
        pm.init();
        try (Rig rig = new Rig(false)) {
            HapticLoop loop = rig.loop(new PhysicalModelAvatar(pm, "hapticMass"));
            loop.useRealUnits();
            loop.setOrigin(-rig.x0, -rig.y0, 0);      // the handle is the model's origin, in metres
            loop.start();
            long deadline = System.nanoTime() + 10_000_000_000L;
            while (loop.ticks() < 1500 && loop.isRunning() && System.nanoTime() < deadline) {
                LockSupport.parkNanos(2_000_000);
            }
            double[] f = new double[2];
            loop.deviceForce(f);
            double t1 = loop.torque(1);
            double t2 = loop.torque(2);
            loop.stop();
            assertTrue(loop.ticks() >= 1500, String.valueOf(loop.failure()));
            assertEquals(0, f[0], 1e-4);
            assertEquals(-0.001 * 9.81, f[1], 0.02 * 0.001 * 9.81, "the weight of 1 g, in newtons");
            // torques are J^T F exactly (gain 1), at the handle's pose
            PantographKinematics k = HaplyPreset.HAPLY_2018.newKinematics();
            double[] th = new double[2];
            assertTrue(k.inverse(rig.x0, rig.y0, th));
            k.forward(th[0], th[1]);
            double[] tau = new double[2];
            k.torques(f[0], f[1], 1.0, tau);
            assertEquals(tau[0], t1, 0.01 * Math.abs(tau[0]) + 1e-6);
            assertEquals(tau[1], t2, 0.01 * Math.abs(tau[1]) + 1e-6);
        }
    }

    /** Holds the model's lock from this thread until the loop has run {@code ticks} more ticks or the time is up. */
    private static long ticksWhileLocked(PhysicalModel pm, HapticLoop loop, long ticks, long maxMillis) {
        long deadline = System.nanoTime() + maxMillis * 1_000_000L;
        pm.getLock().lock();
        try {
            long t0 = loop.ticks();
            while (loop.ticks() - t0 < ticks && System.nanoTime() < deadline && loop.isRunning()) {
                LockSupport.parkNanos(1_000_000);
            }
            return loop.ticks() - t0;
        } finally {
            pm.getLock().unlock();
        }
    }

    private static void awaitTicks(HapticLoop loop, long n) {
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (loop.ticks() < n && loop.isRunning() && System.nanoTime() < deadline) {
            LockSupport.parkNanos(1_000_000);
        }
        assertTrue(loop.ticks() >= n, () -> "the loop ran only " + loop.ticks() + " ticks: " + loop.failure());
    }

    @Test
    void inAudioModeATickNeverWaitsForTheModelsLock() {
        // the audio thread holds the lock for a whole buffer; here the test thread holds it for good
        try (Rig rig = new Rig(false)) {
            PhysicalModel pm = chain(50);
            HapticLoop loop = rig.loop(new PhysicalModelAvatar(pm, "hapticMass"));
            loop.setMode(HapticLoop.Mode.AUDIO);
            assertTrue(loop.isDecoupled());
            loop.start();
            awaitTicks(loop, 20);
            long ran = ticksWhileLocked(pm, loop, 200, 10_000);
            assertTrue(ran >= 200, "ticks while the model was locked: " + ran);
            assertTrue(loop.isRunning(), () -> "loop stopped: " + loop.failure());
            loop.close();
        }
    }

    @Test
    void inAudioModeWithoutDecouplingTheTicksWaitForTheLock() {
        // the counterpart of the test above: it shows that the lock would stall the loop
        try (Rig rig = new Rig(false)) {
            PhysicalModel pm = chain(50);
            HapticLoop loop = rig.loop(new PhysicalModelAvatar(pm, "hapticMass"));
            loop.setMode(HapticLoop.Mode.AUDIO);
            loop.setDecoupledInAudioMode(false);
            loop.setWatchdogMillis(10_000);
            assertFalse(loop.isDecoupled());
            loop.start();
            awaitTicks(loop, 20);
            long ran = ticksWhileLocked(pm, loop, 200, 300);
            assertTrue(ran <= 1, "ticks while the model was locked: " + ran);
            loop.close();
        }
    }

    @Test
    void inAudioModeAModelThatThrowsStopsTheLoopAfterZeroTorque() {
        try (Rig rig = new Rig(false)) {
            AvatarLink failing = new AvatarLink() {
                volatile int calls;

                @Override
                public void setTarget(double x, double y, double z) {
                    if (++calls > 50) {
                        throw new IllegalStateException("diverged on purpose");
                    }
                }

                @Override
                public void takeForce(double[] out) {
                    out[0] = 0.002;
                    out[1] = -0.003;
                    out[2] = 0;
                }

                @Override
                public void step(int n) {
                }
            };
            HapticLoop loop = rig.loop(failing);
            loop.setMode(HapticLoop.Mode.AUDIO);
            loop.start();
            assertStoppedOnDivergenceWithZeroTorque(rig, loop, 10);
        }
    }

    @Test
    void realtimePriorityIsAskedForOnceAndReportedEitherWay() {
        try (Rig rig = new Rig(false)) {
            HapticLoop loop = rig.loop(new FaultyAvatar(Integer.MAX_VALUE, 0, false));
            assertThrows(IllegalArgumentException.class, () -> loop.setRealtimePriority(100));
            assertThrows(IllegalArgumentException.class, () -> loop.setRealtimePriority(-1));
            assertEquals("not started", loop.scheduling());
            loop.setRealtimePriority(10);
            loop.start();
            awaitTicks(loop, 50);
            String s = loop.scheduling();
            assertTrue(s.equals("real-time (SCHED_DEADLINE 800 us of every 1000 us; safety threads at SCHED_FIFO 10; "
                    + "VM and GC threads at 9, JIT compilers at 1)")
                    || s.equals("real-time (SCHED_FIFO 10; VM and GC threads at 9, JIT compilers at 1)")
                    || s.startsWith("normal priority (real-time refused: "), s);
            assertThrows(IllegalStateException.class, () -> loop.setRealtimePriority(0));
            assertThrows(IllegalStateException.class, () -> loop.setDeadlineScheduling(false));
            loop.close();
        }
        try (Rig rig = new Rig(false)) {
            HapticLoop loop = rig.loop(new FaultyAvatar(Integer.MAX_VALUE, 0, false));
            loop.setRealtimePriority(10);
            loop.setDeadlineScheduling(false);
            loop.start();
            awaitTicks(loop, 50);
            String s = loop.scheduling();
            assertTrue(s.equals("real-time (SCHED_FIFO 10; VM and GC threads at 9, JIT compilers at 1)")
                    || s.startsWith("normal priority (real-time refused: "), s);
            loop.close();
        }
        try (Rig rig = new Rig(false)) {
            HapticLoop loop = rig.loop(new FaultyAvatar(Integer.MAX_VALUE, 0, false));
            loop.start();
            awaitTicks(loop, 5);
            assertEquals("normal priority", loop.scheduling());
            loop.close();
        }
    }

    @Test
    void theForceGoesBackAlongTheAxesThePositionCameFrom() {
        // FaultyAvatar's force is (0.002, -0.003) model units; beta 100 makes it 0.2 and -0.3 N
        double[][] expected = {
            {-0.2, -0.3},   // default: alpha > 0, x mirrored
            {0.2, -0.3},    // alpha > 0, no mirror
            {0.2, 0.3},     // alpha < 0 with the mirror: both axes flipped, then x mirrored back
            {-0.2, 0.3},    // alpha < 0, no mirror: a model whose y points the other way
        };
        for (int c = 0; c < 4; c++) {
            try (Rig rig = new Rig(false)) {
                HapticLoop loop = rig.loop(new FaultyAvatar(Integer.MAX_VALUE, 0, false));
                loop.setPositionGain(c < 2 ? 200 : -200);
                loop.setMirrorX(c % 2 == 0);
                loop.start();
                awaitTicks(loop, 20);
                double[] f = new double[2];
                loop.deviceForce(f);
                loop.close();
                assertEquals(expected[c][0], f[0], 1e-9, "case " + c);
                assertEquals(expected[c][1], f[1], 1e-9, "case " + c);
                // and the position map inverts
                double[] m = new double[2];
                double[] d = new double[2];
                loop.deviceToModel(0.03, 0.07, m);
                loop.modelToDevice(m[0], m[1], d);
                assertEquals(0.03, d[0], 1e-12);
                assertEquals(0.07, d[1], 1e-12);
            }
        }
    }

    @Test
    void theWatchdogDoesNotTripWhileTheLoopStartsUp() {
        // the loop thread's start-up (the real-time request runs a program; the first request) may take
        // longer than the watchdog's limit; nothing has been sent yet, so there is nothing to zero
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        Transport link = emulator.connect();
        boolean[] slow = {false};
        Transport slowFirstWrite = new Transport() {
            @Override
            public void write(byte[] data, int offset, int length) throws java.io.IOException {
                if (slow[0]) {
                    slow[0] = false;
                    LockSupport.parkNanos(150_000_000L);
                }
                link.write(data, offset, length);
            }

            @Override
            public int available() throws java.io.IOException {
                return link.available();
            }

            @Override
            public int read(byte[] buffer, int offset, int length) throws java.io.IOException {
                return link.read(buffer, offset, length);
            }

            @Override
            public void close() {
                link.close();
            }

            @Override
            public String describe() {
                return "slow first write";
            }
        };
        Board board = new Board(slowFirstWrite);
        try {
            Device device = new Device((byte) 3, board);
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(),
                    new FaultyAvatar(Integer.MAX_VALUE, 0, false));
            // the loop's first request takes 150 ms, four times the watchdog's limit; once started the loop runs at
            // real-time priority where granted, so that a loaded machine does not make its later ticks that late
            // (at normal priority and a load average of 19 this test saw 2 trips after the start-up)
            loop.setWatchdogMillis(40);
            loop.setRealtimePriority(HapticSession.REALTIME_PRIORITY);
            slow[0] = true;
            loop.start();
            awaitTicks(loop, 50);
            loop.close();
            assertEquals(0, loop.telemetry().watchdogTrips);
        } finally {
            board.close();
        }
    }

    @Test
    void inAudioModeTheForceIsTheMeanPerStepHeldBetweenTheAudioBursts() throws Exception {
        // a constant force on the avatar (a spring to a ground 0.1 away, K 0.5: 0.05 per step), stepped by an
        // audio-like thread in bursts of 1024 steps every 23.2 ms: every tick must render the same force,
        // not nothing between the bursts and a thousand times too much after one
        for (boolean decoupled : new boolean[] {true, false}) {
            try (Rig rig = new Rig(false)) {
                PhysicalModel pm = new PhysicalModel(44100);
                pm.addHapticInput3D("hapticMass", new Vect3D(), 1);
                pm.addGround3D("g", new Vect3D(0.1, 0, 0));
                pm.addSpringDamper3D("k", 0, 0.5, 0, "hapticMass", "g");
                pm.init();
                HapticLoop loop = rig.loop(new PhysicalModelAvatar(pm, "hapticMass"));
                loop.setMode(HapticLoop.Mode.AUDIO);
                loop.setDecoupledInAudioMode(decoupled);
                loop.setForceGain(1);
                loop.start();
                awaitTicks(loop, 20);
                boolean[] stop = {false};
                Thread audio = new Thread(() -> {
                    while (!stop[0]) {
                        pm.computeNSteps(1024);
                        LockSupport.parkNanos(23_200_000L);
                    }
                });
                audio.start();
                try {
                    // wait for two bursts, then sample the rendered force once a millisecond for half a second
                    long two = pm.getStepCount() + 2048;
                    long deadline = System.nanoTime() + 10_000_000_000L;
                    while (pm.getStepCount() < two && System.nanoTime() < deadline) {
                        LockSupport.parkNanos(1_000_000);
                    }
                    // until the loop ticks after a burst it renders nothing (no step has run yet: no force to
                    // render), which is right; a loaded machine may hold the loop's thread back for milliseconds,
                    // so wait for two of its ticks rather than for a fixed time
                    long ticked = loop.ticks() + 2;
                    while (loop.ticks() < ticked && System.nanoTime() < deadline) {
                        LockSupport.parkNanos(1_000_000);
                    }
                    double[] f = new double[2];
                    double[] xs = new double[500];
                    for (int k = 0; k < xs.length; k++) {
                        loop.deviceForce(f);
                        xs[k] = f[0];
                        LockSupport.parkNanos(1_000_000);
                    }
                    assertTrue(loop.isRunning(), () -> "loop stopped: " + loop.failure());
                    // the avatar stays where the still handle puts it (near the origin): F = K (0.1 - x), x mirrored
                    double expected = -0.5 * (0.1 - pm.getMatPosition("hapticMass").x);
                    assertEquals(-0.05, expected, 0.005);
                    for (int k = 0; k < xs.length; k++) {
                        assertEquals(expected, xs[k], Math.abs(expected) * 0.02,
                                "decoupled " + decoupled + ", sample " + k + " of the rendered force");
                    }
                    assertEquals(0, loop.telemetry().faultTicks);
                } finally {
                    stop[0] = true;
                    audio.join(2000);
                    loop.close();
                }
            }
        }
    }

    /** Waits up to {@code seconds} for the loop to stop by itself, and asserts that it did. */
    private static void awaitStop(HapticLoop loop, int seconds) {
        long deadline = System.nanoTime() + seconds * 1_000_000_000L;
        while (loop.isRunning() && System.nanoTime() < deadline) {
            LockSupport.parkNanos(1_000_000);
        }
        assertFalse(loop.isRunning());
    }

    /** The loop stops on the avatar's divergence, and the last torques it sent, and the motors' duties, are zero. */
    private static void assertStoppedOnDivergenceWithZeroTorque(Rig rig, HapticLoop loop, int seconds) {
        awaitStop(loop, seconds);
        assertTrue(loop.failure().contains("diverged on purpose"), loop.failure());
        float[] last = torquesOf(rig.link.last());
        assertEquals(0f, last[0]);
        assertEquals(0f, last[1]);
        assertEquals(0, rig.emulator.duty(1));
        assertEquals(0, rig.emulator.duty(2));
    }
}
