package tactus.haptics.transport;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;
import tactus.haptics.emulator.PtyPair;
import tactus.haptics.Board;
import tactus.haptics.Device;
import tactus.haptics.HaplyLinkException;
import tactus.haptics.HaplyPreset;
import tactus.haptics.Pantograph;

/** The emulator over a real pseudo-terminal made by socat, through jSerialComm: the serial code path. */
class PtyRoundTripTest {

    private static boolean waitForData(Board board, long timeoutMs) {
        long deadline = System.nanoTime() + timeoutMs * 1_000_000L;
        while (!board.data_available()) {
            if (System.nanoTime() > deadline) {
                return false;
            }
            LockSupport.parkNanos(50_000);
        }
        return true;
    }

    @Test
    void hapiFlowOverAPtyAndAnUnplugMidRun() throws Exception {
        Assumptions.assumeTrue(PtyPair.socatAvailable(), "socat is not installed");
        try (PtyPair pty = PtyPair.open()) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
            emulator.setHand(Hand.scripted((t, out) -> {
                out[0] = 0.0;
                out[1] = 0.08;
            }));
            emulator.serve(SerialTransport.open(pty.boardEnd(), 0));
            Board board = new Board(pty.hostEnd(), 0);   // baud 0, as the paper's sketches
            Device d = new Device((byte) 3, board);
            HaplyPreset.HAPLY_2018.configure(d);
            d.device_set_parameters();
            int ok = 0;
            for (int tick = 0; tick < 200; tick++) {
                d.set_device_torques(new float[] {0.5f, -0.25f, 0f});
                d.device_write_torques();
                assertTrue(waitForData(board, 1000), "a reply after write " + tick);
                d.device_read_data();
                ok++;
            }
            assertEquals(200, ok);
            assertEquals(1, emulator.setups());
            assertEquals(200, emulator.writes());
            assertEquals(0, emulator.lateBytes(), "every command arrived whole");
            assertEquals(0, board.idMismatches());
            float[] pos = d.get_device_position(d.get_device_angles());
            assertEquals(0.0, pos[0], 3e-4);
            assertEquals(0.08, pos[1], 3e-4);
            float[] torques = ((Pantograph) d.mechanism()).get_torque();
            double tol = 0.123 / 1023;
            assertEquals(Math.min(Math.abs(torques[0]), 0.123) * Math.signum(torques[0]), emulator.motorTorque(1), tol);
            assertEquals(Math.min(Math.abs(torques[1]), 0.123) * Math.signum(torques[1]), emulator.motorTorque(2), tol);

            // unplug: socat goes away with both ptys
            pty.close();
            HaplyLinkException e = null;
            long giveUp = System.nanoTime() + 5_000_000_000L;
            while (e == null && System.nanoTime() < giveUp) {
                try {
                    d.device_write_torques();
                    d.device_read_data();
                } catch (HaplyLinkException lost) {
                    e = lost;
                }
            }
            assertTrue(e != null, "the lost link is reported");
            assertTrue(board.isClosed());
            board.close();
            assertThrows(HaplyLinkException.class, d::device_write_torques);
        }
    }

    @Test
    void closeZeroesTheMotorsOverThePty() throws Exception {
        Assumptions.assumeTrue(PtyPair.socatAvailable(), "socat is not installed");
        try (PtyPair pty = PtyPair.open()) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.TWO_DIY_V3);
            emulator.serve(SerialTransport.open(pty.boardEnd(), 0));
            Board board = new Board(pty.hostEnd(), 0);
            // the torque is written once and held: the torque watchdog would zero it after 50 ms (on a loaded machine
            // before the test reads it back), and the test would no longer see close() do it
            board.setTorqueWatchdogMillis(0);
            Device d = new Device((byte) 5, board);
            HaplyPreset.TWO_DIY_V3.configure(d);
            d.device_set_parameters();
            d.set_actuator_torque(1, 0.08f);
            d.set_actuator_torque(2, 0.08f);
            d.device_write_torques();
            assertTrue(waitForData(board, 1000));
            d.device_read_data();
            assertArrayEquals(new float[] {360f * 1138 / 2440, 360f * 81 / 2440}, d.get_device_angles());
            assertTrue(emulator.duty(1) > 0 && emulator.duty(2) > 0);
            board.close();
            long deadline = System.nanoTime() + 2_000_000_000L;
            while ((emulator.duty(1) != 0 || emulator.duty(2) != 0) && System.nanoTime() < deadline) {
                LockSupport.parkNanos(1_000_000);
            }
            assertEquals(0, emulator.duty(1));
            assertEquals(0, emulator.duty(2));
            emulator.close();
        }
    }
}
