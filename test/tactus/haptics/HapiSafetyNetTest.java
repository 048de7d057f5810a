package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.transport.Transport;
import tactus.haptics.transport.WireFormat;

/**
 * The hAPI-compatible layer's safety net for a sketch that runs its own ScheduledExecutorService (the
 * paper's way): the executor swallows the task's exception, so the board zeroes the motors by itself and says
 * why on the console.
 */
@Timeout(30)
class HapiSafetyNetTest {
    private final ByteArrayOutputStream console = new ByteArrayOutputStream();
    private PrintStream savedErr;
    private BoardEmulator emulator;
    private Board haplyBoard;
    private Device widgetOne;
    private ScheduledExecutorService scheduler;
    private ZeroWriteClock zeros;
    private volatile long tripsAtThrow = -1;

    @BeforeEach
    void open() {
        savedErr = System.err;
        PrintStream both = new PrintStream(new java.io.OutputStream() {
            @Override
            public void write(int b) {
                synchronized (console) {
                    console.write(b);
                }
                savedErr.write(b);
                if (b == ' ') {
                    // a slow console (the Processing editor's is): a reader may look in the middle of a message
                    java.util.concurrent.locks.LockSupport.parkNanos(50_000);
                }
            }
        }, true, StandardCharsets.UTF_8);
        System.setErr(both);
        emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        zeros = new ZeroWriteClock(emulator.connect());
        haplyBoard = new Board(zeros);
        widgetOne = new Device((byte) 5, haplyBoard);
        HaplyPreset.HAPLY_2018.configure(widgetOne);
        widgetOne.device_set_parameters();
        scheduler = Executors.newScheduledThreadPool(1);
    }

    @AfterEach
    void close() {
        scheduler.shutdownNow();
        haplyBoard.close();
        System.setErr(savedErr);
    }

    private String console() {
        synchronized (console) {
            return console.toString(StandardCharsets.UTF_8);
        }
    }

    /**
     * The console once it holds {@code text}, waiting up to 2 s: the board zeroes the motors before it prints,
     * and the message reaches the console a few bytes at a time, so the test may look in the middle of it.
     */
    private String consoleOnce(String text) {
        long deadline = System.nanoTime() + 2_000_000_000L;
        String out = console();
        while (!out.contains(text) && System.nanoTime() < deadline) {
            java.util.concurrent.locks.LockSupport.parkNanos(1_000_000);
            out = console();
        }
        return out;
    }

    /** The Hello_Wall-style tick: read when data is there, push, write; throws from the sketch at a given tick. */
    private ScheduledFuture<?> sketch(AtomicInteger ticks, int throwAt) {
        float[] force = {0.5f, 0.4f, 0f};
        return scheduler.scheduleAtFixedRate(() -> {
            if (haplyBoard.data_available()) {
                widgetOne.device_read_data();
                float[] angles = widgetOne.get_device_angles();
                widgetOne.get_device_position(new float[] {angles[0], angles[1], 0f});
                widgetOne.set_device_torques(force);
            }
            widgetOne.device_write_torques();
            if (ticks.incrementAndGet() == throwAt) {
                tripsAtThrow = haplyBoard.torqueWatchdogTrips();
                zeros.startFrom(System.nanoTime());
                throw new IllegalStateException("a bug in the sketch's haptic thread");
            }
        }, 1, 1, TimeUnit.MILLISECONDS);
    }

    /** Waits for the task to end with its exception; returns the time it ended (nanoTime). */
    private static long awaitFailure(ScheduledFuture<?> task, Class<? extends Throwable> cause) throws Exception {
        ExecutionException e = assertThrows(ExecutionException.class, () -> task.get(10, TimeUnit.SECONDS),
                "the sketch's task must end with its exception");
        long at = System.nanoTime();
        assertTrue(cause.isInstance(e.getCause()), "cause: " + e.getCause());
        return at;
    }

    /** Milliseconds from t0 until both motors have duty 0 (polled every 0.2 ms), or -1 after 2 s. */
    private long msUntilTorque(long t0) {
        long deadline = t0 + 2_000_000_000L;
        while (System.nanoTime() < deadline) {
            if (emulator.duty(1) > 0 || emulator.duty(2) > 0) {
                return (System.nanoTime() - t0) / 1_000_000;
            }
            java.util.concurrent.locks.LockSupport.parkNanos(200_000);
        }
        return -1;
    }

    private long msUntilZeroTorque(long t0) {
        long deadline = t0 + 2_000_000_000L;
        while (System.nanoTime() < deadline) {
            if (emulator.duty(1) == 0 && emulator.duty(2) == 0) {
                return (System.nanoTime() - t0) / 1_000_000;
            }
            java.util.concurrent.locks.LockSupport.parkNanos(200_000);
        }
        return -1;
    }

    @Test
    void aSketchTaskThatThrowsGetsZeroTorqueWithin100MsAndAMessage() throws Exception {
        AtomicInteger ticks = new AtomicInteger();
        ScheduledFuture<?> task = sketch(ticks, 300);
        long failedAt = awaitFailure(task, IllegalStateException.class);
        long seen = msUntilZeroTorque(failedAt);
        assertTrue(seen >= 0, "the board shows zero torque (seen by polling it) within 2 s of the throw");
        double ms = zeros.millisToFirstZeroWrite();
        System.out.printf("HapiSafetyNetTest: zero torque written %.1f ms after the sketch's task threw (seen by the "
                + "test thread %d ms after it saw the task fail)%n", ms, seen);
        assertTrue(ms >= 0 && ms <= 100, "zero torque within 100 ms of the throw, took " + ms + " ms");
        // one trip for the throw (a CPU hog can delay the task by 50 ms before it, and the watchdog then trips too)
        assertEquals(tripsAtThrow + 1, haplyBoard.torqueWatchdogTrips(), "trips before the throw: " + tripsAtThrow);
        String out = consoleOnce("0 turns it off.)");
        assertTrue(out.contains("no torque was written to the Haply board"), out);
        assertTrue(out.contains("ScheduledExecutorService"), "the message names the likely cause: " + out);
        // the next write drives the motors again
        widgetOne.set_actuator_torque(1, 0.05f);
        widgetOne.set_actuator_torque(2, -0.05f);
        widgetOne.device_write_torques();
        assertTrue(emulator.duty(1) > 0 || emulator.duty(2) > 0);
    }

    /**
     * Times the first write with every torque at zero after a start time, in the thread that makes it (the
     * board's watchdog): the delay of the safety net itself, without the test thread's own scheduling, which
     * under a CPU hog made the polled figure late by tens of milliseconds.
     */
    private static final class ZeroWriteClock implements Transport {
        private final Transport inner;
        private volatile long from;
        private volatile long firstZero;

        ZeroWriteClock(Transport inner) {
            this.inner = inner;
        }

        void startFrom(long nanos) {
            firstZero = 0;
            from = nanos;
        }

        /** Milliseconds from the start to the first all-zero torque write after it, or -1 if none within 2 s. */
        double millisToFirstZeroWrite() throws InterruptedException {
            long deadline = System.nanoTime() + 2_000_000_000L;
            while (firstZero == 0 && System.nanoTime() < deadline) {
                Thread.sleep(1);
            }
            long z = firstZero;
            return z == 0 ? -1 : (z - from) / 1e6;
        }

        @Override
        public void write(byte[] data, int offset, int length) throws IOException {
            inner.write(data, offset, length);
            if (from != 0 && firstZero == 0 && length > 2 && data[offset] == WireFormat.WRITE && allZero(data, offset + 2,
                    length - 2)) {
                firstZero = System.nanoTime();
            }
        }

        private static boolean allZero(byte[] b, int off, int len) {
            for (int i = off; i < off + len; i++) {
                if (b[i] != 0) {
                    return false;
                }
            }
            return true;
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
            inner.close();
        }

        @Override
        public String describe() {
            return inner.describe();
        }
    }

    @Test
    void ourLinkErrorInsideTheExecutorIsPrintedOnceWithTheMotorsZeroed() throws Exception {
        haplyBoard.setTimeoutMillis(10);
        haplyBoard.setLostAfterTimeouts(5);   // lost after 50 ms without a reply
        AtomicInteger ticks = new AtomicInteger();
        ScheduledFuture<?> task = sketch(ticks, Integer.MAX_VALUE);
        while (ticks.get() < 200) {
            Thread.sleep(5);
        }
        assertTrue(emulator.duty(1) > 0 || emulator.duty(2) > 0, "the sketch drives the motors");
        emulator.dropReplies(Integer.MAX_VALUE);   // the board listens but its replies never arrive
        long failedAt = awaitFailure(task, HaplyLinkException.class);
        long ms = msUntilZeroTorque(failedAt);
        assertTrue(ms >= 0 && ms <= 100, "zero torque within 100 ms of the failure, took " + ms + " ms");
        String out = console();
        assertTrue(out.contains("lost the link to the Haply board on emulator while writing"), out);
        assertTrue(out.contains("stopped reading"), out);
        // later calls fail too, without printing again
        assertThrows(HaplyLinkException.class, widgetOne::device_write_torques);
        assertThrows(HaplyLinkException.class, widgetOne::device_read_data);
        assertEquals(1, console().split("lost the link", -1).length - 1, "printed once: " + console());
    }

    @Test
    void callsOnAClosedBoardFailAndArePrintedOnce() {
        haplyBoard.close();
        assertThrows(HaplyLinkException.class, widgetOne::device_write_torques);
        assertThrows(HaplyLinkException.class, widgetOne::device_write_torques);
        String out = console();
        assertEquals(1, out.split("is closed", -1).length - 1, "printed once: " + out);
    }

    @Test
    void theWatchdogCanBeSetAndTurnedOff() throws Exception {
        assertThrows(IllegalArgumentException.class, () -> haplyBoard.setTorqueWatchdogMillis(-1));
        haplyBoard.setTorqueWatchdogMillis(0);
        widgetOne.set_actuator_torque(1, 0.05f);
        widgetOne.set_actuator_torque(2, -0.05f);
        widgetOne.device_write_torques();
        // the emulated board applies the write on its own thread, which a loaded machine may hold back: wait for it
        long arrived = msUntilTorque(System.nanoTime());
        assertTrue(arrived >= 0, "the torque written reaches the board within 2 s");
        Thread.sleep(300);
        assertTrue(emulator.duty(1) > 0 || emulator.duty(2) > 0, "off: a torque written once is held for 300 ms");
        assertEquals(0, haplyBoard.torqueWatchdogTrips());
        haplyBoard.setTorqueWatchdogMillis(20);
        widgetOne.device_write_torques();
        long t0 = System.nanoTime();
        long ms = msUntilZeroTorque(t0);
        assertTrue(ms >= 15 && ms < 1000, "zeroed after about 20 ms, took " + ms + " ms");
    }
}
