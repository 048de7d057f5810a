package tactus.haptics.emulator;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import tactus.haptics.Board;
import tactus.haptics.Device;
import tactus.haptics.HaplyLinkException;
import tactus.haptics.HaplyPreset;

/** The emulator on its own thread behind an in-process transport pair: replies arrive later, as from a board. */
class ThreadedEmulatorTest {

    @Test
    void roundTripPwmAndUnplugThroughATransportPair() {
        TransportPair pair = new TransportPair();
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        emulator.serve(pair.boardEnd());
        Board board = new Board(pair.hostEnd());
        Device d = new Device((byte) 3, board);
        HaplyPreset.HAPLY_2018.configure(d);
        d.add_pwm_pin(13);                // added out of order, pulses set before the setup:
        d.add_pwm_pin(4);                 // each value must still reach its own pin
        d.set_pwm_pulse(13, 100f);
        d.set_pwm_pulse(4, 20f);
        d.device_set_parameters();
        int replies = 0;
        for (int i = 0; i < 100; i++) {
            d.device_write_torques();
            d.device_read_data();         // waits for the reply (the emulator thread answers within a pass)
            replies++;
        }
        assertEquals(100, replies);
        assertEquals(0, board.timeouts());
        assertArrayEquals(new float[] {180f, 0f}, d.get_device_angles());
        assertEquals(255, emulator.pwmPulse(13));
        assertEquals((int) (20f * 255f / 100f), emulator.pwmPulse(4));
        assertEquals(51 * 100f / 255f, d.get_pwm_pulse(4), 1e-4f);   // 20 % is byte 51, read back exactly
        emulator.unplug();
        HaplyLinkException e = assertThrows(HaplyLinkException.class, () -> {
            for (int i = 0; i < 10; i++) {
                d.device_write_torques();
                d.device_read_data();
                LockSupport.parkNanos(1_000_000);
            }
        });
        assertTrue(e.getMessage().contains("cable"), e.getMessage());
        board.close();
    }

    @Test
    void aWaitingReadWakesWhenTheOtherEndWritesAndOtherwiseReturnsNothing() throws Exception {
        TransportPair pair = new TransportPair();
        byte[] buf = new byte[16];
        assertEquals(0, pair.boardEnd().readWaiting(buf, 0, buf.length));   // nothing comes: 0 after the wait
        int[] got = {-1};
        Thread reader = new Thread(() -> {
            try {
                int n = 0;
                while (n == 0) {
                    n = pair.boardEnd().readWaiting(buf, 0, buf.length);
                }
                got[0] = n;
            } catch (java.io.IOException e) {
                got[0] = -2;
            }
        });
        reader.start();
        LockSupport.parkNanos(20_000_000L);
        pair.hostEnd().write(new byte[] {7, 8, 9}, 0, 3);
        reader.join(5000);
        assertEquals(3, got[0]);
        assertArrayEquals(new byte[] {7, 8, 9}, java.util.Arrays.copyOf(buf, 3));
        pair.hostEnd().close();
        assertThrows(java.io.IOException.class, () -> pair.boardEnd().readWaiting(buf, 0, buf.length));
    }
}
