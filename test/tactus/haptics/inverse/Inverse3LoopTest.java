package tactus.haptics.inverse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.AvatarLink;
import tactus.haptics.HapticLoop;
import tactus.haptics.PhysicalModelAvatar;
import tactus.haptics.WorkspaceMapping;
import tactus.haptics.emulator.Hand3D;
import tactus.haptics.emulator.InverseServiceEmulator;
import tactus.haptics.emulator.SimulatedInverse3;

/** The HapticLoop driving an Inverse3 through the Inverse Service client and our emulator. */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class Inverse3LoopTest {
    private static final double[] H = SimulatedInverse3.HOME;

    /** An avatar with a constant force (model units) that allocates nothing. */
    static class ConstantAvatar implements AvatarLink {
        final double fx;
        final double fy;
        final double fz;
        volatile double x;
        volatile double y;
        volatile double z;
        volatile int failAfter = -1;
        int calls;

        ConstantAvatar(double fx, double fy, double fz) {
            this.fx = fx;
            this.fy = fy;
            this.fz = fz;
        }

        @Override
        public void setTarget(double px, double py, double pz) {
            x = px;
            y = py;
            z = pz;
        }

        @Override
        public void takeForce(double[] out) {
            if (failAfter >= 0 && ++calls > failAfter) {
                throw new IllegalStateException("the model diverged (test)");
            }
            out[0] = fx;
            out[1] = fy;
            out[2] = fz;
        }

        @Override
        public void step(int n) {
        }
    }

    static void await(BooleanSupplier done, long millis, String what) {
        long deadline = System.nanoTime() + millis * 1_000_000L;
        while (!done.getAsBoolean()) {
            assertTrue(System.nanoTime() < deadline, "timed out waiting: " + what);
            LockSupport.parkNanos(1_000_000);
        }
    }

    private static double[] last(List<double[]> l) {
        return l.get(l.size() - 1);
    }

    private static void holdAt(InverseServiceEmulator emu, double[] where) {
        emu.device().setHand(Hand3D.scripted((t, out) -> {
            out[0] = where[0];
            out[1] = where[1];
            out[2] = where[2];
        }));
    }

    @Test
    void aModelForceReachesTheDeviceAlongTheMappedAxesUnscaledInRealUnits() {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            holdAt(emu, H);
            emu.setRecording(true);
            Inverse3Device dev = Inverse3Device.open(emu.uri(), 10_000);
            ConstantAvatar a = new ConstantAvatar(1, 2, 3);
            HapticLoop loop = new HapticLoop(dev, a);
            loop.useRealUnits();
            loop.start();
            await(() -> loop.ticks() > 200, 10_000, "200 ticks: " + loop.failure());
            double[] f = new double[3];
            loop.deviceForce(f);
            loop.stop();
            // inverse3YUp: model x = device x, model y = device z, model z = -device y
            assertEquals(1, f[0], 0);
            assertEquals(-3, f[1], 0);
            assertEquals(2, f[2], 0);
            boolean seen = false;
            for (double[] r : emu.receivedForces()) {
                seen |= r[0] == 1 && r[1] == -3 && r[2] == 2;
            }
            assertTrue(seen, "the service received (1, -3, 2) N exactly");
            double[] p = new double[3];
            loop.devicePosition(p);
            assertEquals(H[2], p[2], 1e-12, "the loop reports z too");
            assertEquals(H[0], a.x, 1e-12, "REAL_UNITS: metres in, metres in the model");
            assertEquals(H[2], a.y, 1e-12);
            assertEquals(-H[1], a.z, 1e-12);
            dev.close();
        }
    }

    @Test
    void oneGramHangingFromTheAvatarWeighsNineMilliNewtonsAtTheDevice() {
        PhysicalModel pm = new PhysicalModel(1000, tactus.paramSystem.REAL_UNITS);
        pm.addHapticInput3D("hapticMass", new Vect3D(), 1);
        pm.addMass3D("bob", 0.001, new Vect3D(0, -0.05 - 0.001 * 9.81 / 10, 0), new Vect3D());
        pm.addSpringDamper3D("cord", 0.05, 10, 0.1, "hapticMass", "bob");
        pm.setGravityDirection(new Vect3D(0, 1, 0));
        pm.setGravity(9.81);
        pm.init();
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            holdAt(emu, H);
            try (Inverse3Device dev = Inverse3Device.open(emu.uri(), 10_000)) {
                HapticLoop loop = new HapticLoop(dev, new PhysicalModelAvatar(pm, "hapticMass"));
                loop.useRealUnits();
                loop.setOrigin(-H[0], -H[2], H[1]);    // the handle's home is the model's origin
                loop.start();
                await(() -> loop.ticks() > 1500, 20_000, "1500 ticks: " + loop.failure());
                double[] f = new double[3];
                loop.deviceForce(f);
                loop.stop();
                double[] rendered = new double[3];
                await(() -> {
                    emu.device().force(rendered);
                    return rendered[2] == 0;
                }, 2000, "stop() sends zero force");
                assertEquals(0, f[0], 1e-4);
                assertEquals(0, f[1], 1e-4);
                assertEquals(-0.001 * 9.81, f[2], 0.02 * 0.001 * 9.81, "the weight of 1 g, in newtons, downwards (device z)");
            }
        }
    }

    @Test
    void theHapticInput3DMovesInAllThreeAxesThroughAPermutedScaledMirroredMapping() {
        PhysicalModel pm = new PhysicalModel(1000, tactus.paramSystem.REAL_UNITS);
        pm.addHapticInput3D("avatar", new Vect3D(10, 20, 30), 1);
        pm.init();
        // model x = device z, model y = device x, model z = -device y: a permutation that flips handedness
        WorkspaceMapping m = WorkspaceMapping.of("z,x,-y").withScale(100).centring(H, 10, 20, 30);
        assertFalse(m.keepsHandedness());
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            double[] where = H.clone();
            holdAt(emu, where);
            try (Inverse3Device dev = Inverse3Device.open(emu.uri(), 10_000)) {
                HapticLoop loop = new HapticLoop(dev, new PhysicalModelAvatar(pm, "avatar"));
                loop.setWorkspaceMapping(m);
                loop.setForceGain(0);
                loop.start();
                double[][] points = {{0.05, 0, 0}, {0, 0.04, 0}, {0, 0, -0.03}, {-0.02, -0.03, 0.05}};
                double[] model = new double[3];
                for (double[] d : points) {
                    for (int i = 0; i < 3; i++) {
                        where[i] = H[i] + d[i];
                    }
                    long t0 = loop.ticks();
                    await(() -> loop.ticks() > t0 + 400, 20_000, "400 ticks: " + loop.failure());
                    m.toModel(where, model);
                    Vect3D got = pm.getMatPosition("avatar");
                    assertEquals(model[0], got.x, 0.01, "model x follows device z for " + java.util.Arrays.toString(d));
                    assertEquals(model[1], got.y, 0.01, "model y follows device x");
                    assertEquals(model[2], got.z, 0.01, "model z follows -device y");
                }
                // each device axis moved its own model axis, by 100 model units per metre
                assertEquals(20 + 100 * -0.02, pm.getMatPosition("avatar").y, 0.01);
                assertEquals(10 + 100 * 0.05, pm.getMatPosition("avatar").x, 0.01);
                assertEquals(30 - 100 * -0.03, pm.getMatPosition("avatar").z, 0.01);
                loop.stop();
            }
        }
    }

    @Test
    void aModelThatThrowsGetsZeroForceAndStopsTheLoop() {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            holdAt(emu, H);
            emu.setRecording(true);
            try (Inverse3Device dev = Inverse3Device.open(emu.uri(), 10_000)) {
                ConstantAvatar a = new ConstantAvatar(0.5, 0, 0);
                a.failAfter = 300;
                HapticLoop loop = new HapticLoop(dev, a);
                loop.useRealUnits();
                loop.start();
                await(() -> !loop.isRunning(), 10_000, "the loop stops");
                assertNotNull(loop.failure());
                assertTrue(loop.failure().contains("zero force sent") && loop.failure().contains("diverged"), loop.failure());
                await(() -> emu.receivedForces().size() > 0 && last(emu.receivedForces())[0] == 0, 2000, "zero force arrives");
                double[] f = new double[3];
                emu.device().force(f);
                assertEquals(0, f[0], 0);
            }
        }
    }

    @Test
    void closingTheLoopSendsZeroForceAndClosesTheConnection() {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            holdAt(emu, H);
            emu.setRecording(true);
            Inverse3Device dev = Inverse3Device.open(emu.uri(), 10_000);
            HapticLoop loop = new HapticLoop(dev, new ConstantAvatar(0, 1, 0));
            loop.useRealUnits();
            loop.start();
            await(() -> loop.ticks() > 100, 10_000, "100 ticks");
            loop.close();
            assertTrue(dev.client().isClosed());
            await(() -> emu.zeroedOnDisconnect() == 1, 2000, "the connection ends");
            double[] lastSent = last(emu.receivedForces());
            assertEquals(0, lastSent[0] + lastSent[1] + lastSent[2], 0, "the last force we sent was zero");
        }
    }

    @Test
    void aStalledTickGetsZeroForceFromTheWatchdog() {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            holdAt(emu, H);
            emu.setRecording(true);
            try (Inverse3Device dev = Inverse3Device.open(emu.uri(), 10_000)) {
                ConstantAvatar a = new ConstantAvatar(0.5, 0, 0) {
                    int steps;

                    @Override
                    public void step(int n) {
                        if (++steps == 300) {
                            LockSupport.parkNanos(150_000_000L);   // a 150 ms stall inside one tick
                        }
                    }
                };
                HapticLoop loop = new HapticLoop(dev, a);
                loop.useRealUnits();
                loop.start();
                await(() -> loop.ticks() > 500, 10_000, "500 ticks: " + loop.failure());
                loop.stop();
                assertTrue(loop.telemetry().watchdogTrips >= 1, "the watchdog tripped");
                List<double[]> got = emu.receivedForces();
                int zeroBetween = 0;
                boolean pushedBefore = false;
                for (double[] f : got) {
                    if (f[0] == 0.5) {
                        pushedBefore = true;
                    } else if (pushedBefore && f[0] == 0) {
                        zeroBetween++;
                        break;
                    }
                }
                assertTrue(zeroBetween > 0, "a zero force went out while the tick was stalled");
            }
        }
    }

    @Test
    void aServiceThatDropsTheSocketStopsTheLoopWithAMessage() {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            holdAt(emu, H);
            try (Inverse3Device dev = Inverse3Device.open(emu.uri(), 10_000)) {
                HapticLoop loop = new HapticLoop(dev, new ConstantAvatar(0, 0, 0));
                loop.start();
                await(() -> loop.ticks() > 100, 10_000, "100 ticks");
                long t0 = System.nanoTime();
                emu.dropConnections();
                await(() -> !loop.isRunning(), 2000, "the loop stops");
                long ms = (System.nanoTime() - t0) / 1_000_000;
                System.out.println("Inverse3 loop: stopped " + ms + " ms after the service dropped the socket: " + loop.failure());
                assertTrue(loop.failure().contains("Inverse Service"), loop.failure());
                assertTrue(ms < 1000, ms + " ms");
            }
        }
    }

    @Test
    void aServiceThatStopsAnsweringStopsTheLoopAfterTheLinkTimeout() {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            holdAt(emu, H);
            try (Inverse3Device dev = Inverse3Device.open(emu.uri(), 10_000)) {
                HapticLoop loop = new HapticLoop(dev, new ConstantAvatar(0, 0, 0));
                // 500 ms, a real device's timeout: a loaded machine can hold the emulator's normal-priority thread
                // back for more than 50 ms, which stopped the loop before the service went silent
                loop.setLinkTimeoutMillis(500);
                loop.start();
                await(() -> loop.ticks() > 100 || !loop.isRunning(), 10_000, "100 ticks");
                assertTrue(loop.isRunning(), "the loop runs while the service answers: " + loop.failure());
                emu.setMute(true);
                await(() -> !loop.isRunning(), 5000, "the loop stops");
                assertTrue(loop.failure().contains("no state from Haply inverse3"), loop.failure());
                assertTrue(dev.client().isClosed(), "the connection was closed after sending zero force");
            }
        }
    }

    /** The measured figures (printed) of docs/haptics.md: round trip per tick and allocation per tick. */
    @Test
    void roundTripAndAllocationPerTick() {
        java.lang.management.ThreadMXBean base = ManagementFactory.getThreadMXBean();
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) base;
        mx.setThreadAllocatedMemoryEnabled(true);
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            emu.device().setHand(Hand3D.scripted((t, out) -> {
                out[0] = H[0] + 0.02 * Math.sin(t);
                out[1] = H[1] + 0.02 * Math.cos(t);
                out[2] = H[2] + 0.01 * Math.sin(2 * t);
            }));
            try (Inverse3Device dev = Inverse3Device.open(emu.uri(), 10_000)) {
                ConstantAvatar a = new ConstantAvatar(0.1, 0.2, 0.3);
                HapticLoop loop = new HapticLoop(dev, a);
                loop.useRealUnits();
                loop.start();
                await(() -> loop.ticks() > 1000, 10_000, "warm-up");
                Thread haptic = null;
                for (Thread t : Thread.getAllStackTraces().keySet()) {
                    if (t.getName().equals("tactus-haptic-loop")) {
                        haptic = t;
                    }
                }
                assertNotNull(haptic);
                long[] ids = clientThreads();
                long clientBefore = sum(mx.getThreadAllocatedBytes(ids));
                long hapticBefore = mx.getThreadAllocatedBytes(haptic.getId());
                long ticksBefore = loop.ticks();
                long rtBefore = dev.client().roundTripCount();
                LockSupport.parkNanos(3_000_000_000L);
                long hapticAfter = mx.getThreadAllocatedBytes(haptic.getId());
                long clientAfter = sum(mx.getThreadAllocatedBytes(ids));
                long ticks = loop.ticks() - ticksBefore;
                InverseServiceClient c = dev.client();
                String figures = String.format(java.util.Locale.ROOT,
                        "Inverse3 loop over the emulator: %d ticks in 3 s, round trip p50 %d us, p99 %d us, max %d us (%d measured); "
                        + "allocated per tick: haptic thread %.0f B, client threads (haptic + socket) %.0f B; %s",
                        ticks, c.roundTripNanos(0.5) / 1000, c.roundTripNanos(0.99) / 1000, c.roundTripNanos(1.0) / 1000,
                        c.roundTripCount() - rtBefore, (hapticAfter - hapticBefore) / (double) ticks,
                        (clientAfter - clientBefore) / (double) ticks, loop.telemetry());
                System.out.println(figures);
                loop.stop();
                assertTrue(ticks > 1500, figures);
                assertTrue(c.roundTripNanos(0.5) < 5_000_000, figures);
                assertTrue((hapticAfter - hapticBefore) / (double) ticks < 2048, "the send allocates, but boundedly: " + figures);
            }
        }
    }

    private static long[] clientThreads() {
        return Thread.getAllStackTraces().keySet().stream()
                .filter(t -> !t.getName().startsWith("tactus-inverse-emulator"))
                .mapToLong(Thread::getId).toArray();
    }

    private static long sum(long[] v) {
        long s = 0;
        for (long x : v) {
            if (x > 0) {
                s += x;
            }
        }
        return s;
    }
}
