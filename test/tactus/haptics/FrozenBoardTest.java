package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.time.Duration;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.PtyPair;
import tactus.haptics.safety.MotorGuard;
import tactus.haptics.transport.SerialTransport;
import tactus.haptics.transport.Transport;

/**
 * A board that stops reading while its port stays open (socat alive, the emulator's end closed): writes fill
 * the driver's buffer and then must neither spin nor block for ever.
 */
class FrozenBoardTest {

    @Test
    void aWriteThatCannotCompleteFailsWithinTheWriteTimeoutWithoutSpinning() throws Exception {
        Assumptions.assumeTrue(PtyPair.socatAvailable(), "socat is not installed");
        try (PtyPair pty = PtyPair.open()) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
            emulator.serve(SerialTransport.open(pty.boardEnd(), 0));
            SerialTransport host = SerialTransport.open(pty.hostEnd(), 0);
            emulator.unplug();   // the board side is gone, the pty pair stays
            assertTrue(pty.isAlive());
            ThreadMXBean threads = ManagementFactory.getThreadMXBean();
            byte[] chunk = new byte[4096];
            long[] stalledFor = new long[1];
            long[] cpu = new long[1];
            IOException e = assertTimeoutPreemptively(Duration.ofSeconds(20), () -> {
                long cpu0 = threads.getCurrentThreadCpuTime();
                try {
                    long previousStart = 0;
                    for (int i = 0; i < 10_000; i++) {   // at most 40 MB: the buffer is far smaller
                        long t0 = System.nanoTime();
                        try {
                            host.write(chunk, 0, chunk.length);
                        } catch (IOException failed) {
                            long end = System.nanoTime();
                            // Under load a write can complete just as the guard times it out: the guard has closed
                            // the port, so it is the next write that fails, at once. The stall is then the one of
                            // the write before.
                            boolean failedAtOnce = end - t0 < SerialTransport.WRITE_TIMEOUT_MS * 500_000L;
                            stalledFor[0] = end - (failedAtOnce && previousStart != 0 ? previousStart : t0);
                            return failed;
                        }
                        previousStart = t0;
                    }
                    return null;
                } finally {
                    cpu[0] = threads.getCurrentThreadCpuTime() - cpu0;
                }
            }, "a write to a board that stopped reading must end");
            assertNotNull(e, "the writes must fail once the buffer is full");
            assertTrue(e.getMessage().contains("did not complete within " + SerialTransport.WRITE_TIMEOUT_MS), e.getMessage());
            long stalledMs = stalledFor[0] / 1_000_000;
            assertTrue(stalledMs >= SerialTransport.WRITE_TIMEOUT_MS - 10 && stalledMs < 1_000,
                    "the blocked write ends after the write timeout, took " + stalledMs + " ms");
            // filling the buffer costs a few ms; a spinning write would take the whole stall as CPU
            assertTrue(cpu[0] < stalledFor[0] / 2, "CPU " + cpu[0] / 1_000_000 + " ms during a stall of " + stalledMs + " ms");
            IOException again = assertThrows(IOException.class, () -> host.write(chunk, 0, 1), "the stalled port stays "
                    + "closed");
            IOException reading = assertThrows(IOException.class, () -> host.available(), "a read fails too");
            for (IOException later : new IOException[] {again, reading}) {
                assertTrue(later.getMessage().contains("did not complete within " + SerialTransport.WRITE_TIMEOUT_MS),
                        "a later call says why the port was closed: " + later.getMessage());
            }
            System.out.println("FrozenBoardTest: blocked write failed after " + stalledMs + " ms, thread CPU "
                    + cpu[0] / 1_000_000 + " ms");
            host.close();
        }
    }

    @Test
    void theHapticLoopStopsOnAFrozenBoardEvenWithALongLinkTimeout() throws Exception {
        Assumptions.assumeTrue(PtyPair.socatAvailable(), "socat is not installed");
        try (PtyPair pty = PtyPair.open()) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
            emulator.serve(SerialTransport.open(pty.boardEnd(), 0));
            Board board = new Board(pty.hostEnd(), 0);
            Device device = new Device((byte) 3, board);
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), new ConstantForce(0.2, 0.1));
            loop.setLinkTimeoutMillis(600_000);   // the loop's own stale-reply limit would never fire
            loop.setWatchdogMillis(1000);
            loop.start();
            try {
                long deadline = System.nanoTime() + 10_000_000_000L;
                while (loop.ticks() < 200 && System.nanoTime() < deadline) {
                    Thread.sleep(5);
                }
                assertTrue(loop.ticks() >= 200, "the loop runs");
                long frozenAt = System.nanoTime();
                emulator.unplug();
                assertTimeoutPreemptively(Duration.ofSeconds(8), () -> {
                    while (loop.isRunning()) {
                        Thread.sleep(5);
                    }
                }, "the loop must stop on a board that stopped reading");
                long ms = (System.nanoTime() - frozenAt) / 1_000_000;
                assertNotNull(loop.failure());
                assertTrue(loop.failure().contains("stopped reading"), loop.failure());
                assertTrue(board.isClosed());
                System.out.println("FrozenBoardTest: the haptic loop stopped " + ms + " ms after the board froze: " + loop.failure());
                assertNotNull(board.lostReason(), "the board says why");
            } finally {
                pty.close();   // first: a write stuck in the port (the defect) then fails instead of hanging close()
                loop.close();
            }
        }
    }

    /**
     * Behind a serial write that is stuck (the board stopped reading, the pty's buffer is full), close() and
     * zeroTorques() (a watchdog's call) wait at most {@link Board#STUCK_WRITE_NANOS} of their own, not until the
     * write's own timeout ends it: before, both waited for that, 230-250 ms after a write stuck for 30 ms, every
     * run.
     */
    @Test
    void closeAndZeroTorquesWaitAtMost50MsBehindAStuckSerialWrite() throws Exception {
        Assumptions.assumeTrue(PtyPair.socatAvailable(), "socat is not installed");
        for (boolean closeIt : new boolean[] {false, true}) {
            // an attempt is inconclusive when the stuck write ended (the port's 250 ms write timeout) before the call
            // returned: beside a CPU hog the test thread may first see the write stuck 200 ms late; then try again
            for (int attempt = 1; ; attempt++) {
                try (PtyPair pty = PtyPair.open()) {
                    BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
                    emulator.serve(SerialTransport.open(pty.boardEnd(), 0));
                    Board board = new Board(pty.hostEnd(), 0);
                    board.setLostAfterTimeouts(100_000);   // the board's own lost-link time would stop the writer first
                    Device device = new Device((byte) 5, board);
                    HaplyPreset.HAPLY_2018.configure(device);
                    device.device_set_parameters();
                    emulator.unplug();
                    long[] inWriteSince = new long[1];
                    Thread writer = new Thread(() -> {
                        try {
                            while (true) {
                                device.set_actuator_torque(1, 0.05f);
                                inWriteSince[0] = System.nanoTime();
                                device.device_write_torques();
                                inWriteSince[0] = 0;
                            }
                        } catch (RuntimeException e) {
                            // the link is lost: expected
                        }
                    }, "filling-writer");
                    writer.setDaemon(true);
                    writer.start();
                    try {
                        long deadline = System.nanoTime() + 10_000_000_000L;
                        long since = 0;
                        boolean stuck = false;
                        while (!stuck && System.nanoTime() < deadline) {
                            Thread.sleep(1);
                            since = inWriteSince[0];
                            // in a write for 30 ms and asleep in the kernel's tty write, not merely a thread the
                            // loaded machine did not run
                            stuck = since != 0 && System.nanoTime() - since > 30_000_000L && asleepInTtyWrite("filling-writer");
                        }
                        assertTrue(stuck, "a write gets stuck once the buffer is full");
                        long stuckMs = (System.nanoTime() - since) / 1_000_000;
                        long t0 = System.nanoTime();
                        String what = closeIt ? "close()" : "zeroTorques()";
                        boolean zeroSent = false;
                        if (closeIt) {
                            board.close();
                            assertTrue(board.isClosed());
                        } else {
                            zeroSent = board.zeroTorques();
                        }
                        double ms = (System.nanoTime() - t0) / 1e6;
                        boolean timeoutMayHaveEnded = stuckMs + ms >= SerialTransport.WRITE_TIMEOUT_MS - 50;
                        // the emulator's reader may drain the buffer once more as it is unplugged: the write then
                        // completes, and a zero behind it rightly goes out
                        boolean cameUnstuck = inWriteSince[0] != since;
                        if ((timeoutMayHaveEnded || cameUnstuck) && attempt < 3) {
                            String why = cameUnstuck ? "the write completed during the call"
                                    : "its own " + SerialTransport.WRITE_TIMEOUT_MS + " ms timeout may have ended it";
                            System.out.printf("FrozenBoardTest: attempt %d inconclusive: the write was stuck for %d ms "
                                    + "and %s took %.1f ms, so %s; trying again%n", attempt, stuckMs, what, ms, why);
                            continue;
                        }
                        assertTrue(!zeroSent, "no zero can go out behind a stuck write (stuck " + stuckMs
                                + " ms when called; the call took " + ms + " ms; attempt " + attempt + ")");
                        double waited = board.lastLockWaitNanos() / 1e6;
                        System.out.printf("FrozenBoardTest: %s behind a write stuck for %d ms waited %.1f ms for the "
                                + "board, returned after %.1f ms%n", what, stuckMs, waited, ms);
                        // the wait behind the stuck write is the board's to bound; closing the port after it is
                        // jSerialComm's (once 460 ms in a loaded full run), so the whole call only has a hang bound
                        assertTrue(waited < 150, what + " waited " + waited + " ms behind a stuck write (the bound is "
                                + Board.STUCK_WRITE_NANOS / 1_000_000 + " ms of its own)");
                        assertTrue(ms < 2_000, what + " took " + ms + " ms in all");
                    } finally {
                        board.close();
                        writer.join(2_000);
                        Process guard = board.guardLink().process();
                        if (guard != null) {
                            guard.waitFor(MotorGuard.ACT_LIMIT_MS + 2_000, java.util.concurrent.TimeUnit.MILLISECONDS);
                        }
                    }
                }
                break;
            }
        }
    }

    /**
     * True if this JVM's thread of that name is asleep in the kernel in a tty write (Linux: /proc). Other threads may
     * end while the tasks are listed: their folders are skipped.
     */
    private static boolean asleepInTtyWrite(String threadName) throws IOException {
        java.nio.file.Path tasks = java.nio.file.Paths.get("/proc/self/task");
        try (java.util.stream.Stream<java.nio.file.Path> all = java.nio.file.Files.list(tasks)) {
            for (java.nio.file.Path t : (Iterable<java.nio.file.Path>) all::iterator) {
                try {
                    String comm = new String(java.nio.file.Files.readAllBytes(t.resolve("comm"))).trim();
                    if (comm.equals(threadName)) {
                        String stat = new String(java.nio.file.Files.readAllBytes(t.resolve("stat")));
                        String wchan = new String(java.nio.file.Files.readAllBytes(t.resolve("wchan")));
                        char state = stat.charAt(stat.lastIndexOf(')') + 2);
                        return state == 'S' && !wchan.contains("futex");
                    }
                } catch (java.nio.file.NoSuchFileException ended) {
                    // a thread of the JVM (not the writer, which is still in its write) ended after the listing
                }
            }
        }
        return false;
    }

    @Test
    void closeNeverWaitsForAWriteStuckInTheTransport() throws Exception {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        StuckTransport link = new StuckTransport(emulator.connect());
        Board board = new Board(link);
        Device device = new Device((byte) 3, board);
        HaplyPreset.HAPLY_2018.configure(device);
        device.device_set_parameters();
        device.set_actuator_torque(1, 0.05f);
        link.freeze();
        RuntimeException[] failure = new RuntimeException[1];
        Thread writer = new Thread(() -> {
            try {
                device.device_write_torques();   // blocks in the transport, holding the board
            } catch (RuntimeException e) {
                failure[0] = e;
            }
        }, "stuck-writer");
        writer.setDaemon(true);
        writer.start();
        assertTrue(link.stuck.await(5, java.util.concurrent.TimeUnit.SECONDS), "the write is stuck");
        long t0 = System.nanoTime();
        assertTimeoutPreemptively(Duration.ofSeconds(5), board::close, "close() must not wait for the stuck write");
        long ms = (System.nanoTime() - t0) / 1_000_000;
        writer.join(2000);
        assertTrue(!writer.isAlive(), "closing the transport ends the stuck write");
        assertTrue(failure[0] instanceof HaplyLinkException, "the writer learns the link is gone: " + failure[0]);
        assertTrue(board.isClosed());
        assertTrue(ms < 2000, "close() took " + ms + " ms");
        System.out.println("FrozenBoardTest: close() beside a stuck write returned after " + ms + " ms");
    }

    /** A transport whose writes, once frozen, block until the transport is closed (as a blocked serial write). */
    private static final class StuckTransport implements Transport {
        private final Transport inner;
        final java.util.concurrent.CountDownLatch stuck = new java.util.concurrent.CountDownLatch(1);
        private final java.util.concurrent.CountDownLatch closed = new java.util.concurrent.CountDownLatch(1);
        private volatile boolean frozen;

        StuckTransport(Transport inner) {
            this.inner = inner;
        }

        void freeze() {
            frozen = true;
        }

        @Override
        public void write(byte[] data, int offset, int length) throws IOException {
            if (frozen) {
                stuck.countDown();
                try {
                    closed.await();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                throw new IOException("closed while the write was blocked");
            }
            inner.write(data, offset, length);
        }

        @Override
        public int available() throws IOException {
            return inner.available();
        }

        @Override
        public int read(byte[] buffer, int offset, int length) throws IOException {
            return inner.read(buffer, offset, length);
        }

        @Override
        public void close() {
            closed.countDown();
            inner.close();
        }

        @Override
        public String describe() {
            return "stuck transport";
        }
    }

    /** A model stand-in whose avatar pushes with a constant force (model units). */
    private static final class ConstantForce implements AvatarLink {
        private final double fx;
        private final double fy;

        ConstantForce(double fx, double fy) {
            this.fx = fx;
            this.fy = fy;
        }

        @Override
        public void setTarget(double x, double y, double z) {
            // the force does not depend on the position
        }

        @Override
        public void takeForce(double[] out) {
            out[0] = fx;
            out[1] = fy;
            out[2] = 0;
        }

        @Override
        public void step(int n) {
            // nothing to step
        }
    }
}
