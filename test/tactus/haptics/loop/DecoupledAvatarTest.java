package tactus.haptics.loop;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import tactus.haptics.AvatarLink;

/** The decoupled avatar: the haptic side never waits, and no force is lost or counted twice. */
class DecoupledAvatarTest {

    /** A slow model: each exchange holds a lock for a while and adds a known force. */
    private static final class SlowLink implements AvatarLink {
        volatile double lastX;
        long calls;
        final Object lock = new Object();

        @Override
        public void setTarget(double x, double y, double z) {
            synchronized (lock) {
                lastX = x;
            }
        }

        @Override
        public void takeForce(double[] out) {
            synchronized (lock) {
                LockSupport.parkNanos(300_000);
                calls++;
                out[0] = 1;
                out[1] = 2;
                out[2] = 0.5;
            }
        }

        @Override
        public void step(int n) {
        }
    }

    @Test
    void everyForceArrivesExactlyOnceAndTheTargetGetsThrough() {
        SlowLink slow = new SlowLink();
        double[] sum = new double[3];
        double[] f = new double[3];
        try (DecoupledAvatar a = new DecoupledAvatar(slow)) {
            for (int i = 0; i < 300; i++) {
                a.setTarget(i, 0, 0);
                a.takeForce(f);
                sum[0] += f[0];
                sum[1] += f[1];
                sum[2] += f[2];
                LockSupport.parkNanos(200_000);
            }
            long deadline = System.nanoTime() + 2_000_000_000L;
            while (slow.lastX != 299 && System.nanoTime() < deadline) {
                LockSupport.parkNanos(1_000_000);
            }
            LockSupport.parkNanos(20_000_000);
            a.takeForce(f);
            sum[0] += f[0];
            sum[1] += f[1];
            sum[2] += f[2];
            assertEquals(299.0, slow.lastX, "the newest target reached the model");
            long calls;
            synchronized (slow.lock) {
                calls = slow.calls;
            }
            assertTrue(calls > 10, "exchanges: " + calls);
            assertEquals(calls, a.exchanges());
            // the totals handed out equal the totals produced: nothing lost, nothing twice
            assertEquals(calls * 1.0, sum[0], 1e-9);
            assertEquals(calls * 2.0, sum[1], 1e-9);
            assertEquals(calls * 0.5, sum[2], 1e-9);
        }
    }

    @Test
    void aFailingModelMakesTakeForceThrowWithTheModelsException() {
        AvatarLink failing = new AvatarLink() {
            @Override
            public void setTarget(double x, double y, double z) {
                throw new IllegalStateException("diverged");
            }

            @Override
            public void takeForce(double[] out) {
            }

            @Override
            public void step(int n) {
            }
        };
        double[] f = new double[3];
        try (DecoupledAvatar a = new DecoupledAvatar(failing)) {
            a.setTarget(1, 2, 3);
            long deadline = System.nanoTime() + 2_000_000_000L;
            while (a.exchanges() == 0 && System.nanoTime() < deadline) {
                LockSupport.parkNanos(1_000_000);
            }
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> a.takeForce(f));
            assertTrue(e.getMessage().contains("diverged"), e.getMessage());
        }
    }

    @Test
    void theStepCountsArriveWithTheirForcesAndAnUncountedLinkSaysSo() {
        // each exchange reports 7 steps and a force of 7 (1 per step): the haptic side must see them together
        AvatarLink counted = countedLink(7, 7);
        double[] f = new double[3];
        try (DecoupledAvatar a = new DecoupledAvatar(counted)) {
            long steps = 0;
            double sum = 0;
            for (int i = 0; i < 200; i++) {
                a.setTarget(i, 0, 0);
                long n = a.takeForceCounted(f);
                assertTrue(n >= 0, "count " + n);
                assertEquals(n, f[0], 1e-9, "a force of 1 per step");
                steps += n;
                sum += f[0];
                LockSupport.parkNanos(200_000);
            }
            assertTrue(steps > 0);
            assertEquals(steps, sum, 1e-9);
        }
        try (DecoupledAvatar a = new DecoupledAvatar(new SlowLink())) {
            a.setTarget(1, 0, 0);
            long deadline = System.nanoTime() + 2_000_000_000L;
            while (a.exchanges() == 0 && System.nanoTime() < deadline) {
                LockSupport.parkNanos(1_000_000);
            }
            assertEquals(-1, a.takeForceCounted(f), "a link that cannot count");
        }
    }

    @Test
    void theHapticSideNeverWaitsForAHelperCaughtMidPublication() throws Exception {
        // a helper preempted between the two halves of a publication leaves the sequence odd; the haptic
        // thread (perhaps real-time) must not spin until it runs again
        AvatarLink counted = countedLink(2, 1);
        double[] f = new double[3];
        try (DecoupledAvatar a = new DecoupledAvatar(counted)) {
            a.setTarget(0, 0, 0);
            long deadline = System.nanoTime() + 2_000_000_000L;
            while (a.exchanges() == 0 && System.nanoTime() < deadline) {
                LockSupport.parkNanos(1_000_000);
            }
            java.lang.reflect.Field seq = DecoupledAvatar.class.getDeclaredField("forceSeq");
            seq.setAccessible(true);
            long even = seq.getLong(a);
            seq.setLong(a, even + 1);                  // "writing", and the writer does not come back
            long n = org.junit.jupiter.api.Assertions.assertTimeoutPreemptively(java.time.Duration.ofSeconds(5),
                    () -> a.takeForceCounted(f));
            assertEquals(0, n);
            assertEquals(0.0, f[0]);
            assertEquals(1, a.busyReads());
            seq.setLong(a, even);                      // the writer finishes: everything arrives, once
            long exchanges = a.exchanges();
            assertEquals(exchanges, a.takeForceCounted(f));
            assertEquals(2.0 * exchanges, f[0], 1e-12);
        }
    }

    /** A link whose every take reports {@code steps} steps and a force of {@code fx} along x. */
    private static AvatarLink countedLink(double fx, long steps) {
        return new AvatarLink() {
            @Override
            public void setTarget(double x, double y, double z) {
            }

            @Override
            public void takeForce(double[] out) {
                takeForceCounted(out);
            }

            @Override
            public long takeForceCounted(double[] out) {
                out[0] = fx;
                out[1] = 0;
                out[2] = 0;
                return steps;
            }

            @Override
            public void step(int n) {
            }
        };
    }
}
