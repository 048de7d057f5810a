package tactus.haptics.emulator;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.haptics.Board;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.transport.Transport;

/** The emulator does what the M0 firmware does where the two used to differ: the duty's division, and id 0. */
class FirmwareFidelityTest {

    /** The firmware: (float)(1023 * |tau| clipped) divided by the double constant 0.123, truncated. */
    private static int firmwareDuty(float tau) {
        float mag = Math.min(Math.abs(tau), (float) 0.123);
        return (int) ((float) (1023 * mag) / 0.123);
    }

    @Test
    void dutyIsDividedByTheDoubleConstantAtEveryBoundary() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        Board board = new Board(emulator.connect());
        try {
            board.setTorqueWatchdogMillis(0);
            Device d = new Device((byte) 3, board);
            HaplyPreset.HAPLY_2018.configure(d);
            d.device_set_parameters();
            int tried = 0;
            int wrong = 0;
            StringBuilder first = new StringBuilder();
            for (int duty = 1; duty <= 1023; duty++) {
                float at = (float) (duty * 0.123 / 1023);
                for (float tau : new float[] {Math.nextDown(at), at, Math.nextUp(at)}) {
                    d.set_actuator_torque(1, tau);
                    d.set_actuator_torque(2, -tau);
                    d.device_write_torques();
                    d.device_read_data();
                    tried++;
                    for (int port = 1; port <= 2; port++) {
                        if (emulator.duty(port) != firmwareDuty(tau)) {
                            if (wrong++ < 3) {
                                first.append(" tau=").append(tau).append(": ").append(emulator.duty(port))
                                        .append(" instead of ").append(firmwareDuty(tau));
                            }
                        }
                    }
                }
            }
            assertEquals(3069, tried);
            assertEquals(0, wrong, wrong + " duties differ from the firmware's:" + first);
        } finally {
            board.close();
        }
    }

    @Test
    void aWriteWithIdZeroClaimsEveryFreePinAndSlotLikeTheFirmware() throws Exception {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        Transport link = emulator.connect();
        Board board = new Board(link);
        try {
            Device d = new Device((byte) 3, board);
            HaplyPreset.HAPLY_2018.configure(d);   // 2 motors, 2 encoders: no analog input, no PWM pin
            d.device_set_parameters();
            byte[] pulses = new byte[14];
            pulses[4] = (byte) 128;
            board.transmit((byte) 2, (byte) 0, pulses, null);   // both motors are taken: no torque float
            assertEquals(21, link.available(), "id 0 claims the 5 free analog slots: [00] and 5 floats");
            float[] values = board.receive((byte) 2, (byte) 0, 5);
            assertArrayEquals(new float[5], values, "analog slots never set up read 0");
            assertEquals(128, emulator.pwmPulse(4), "the pulse byte for free pin 4 was taken");
            assertEquals(0, emulator.unknownBytes(), "no pulse byte was read as a command");
            assertEquals(0, emulator.lateBytes());
            assertEquals(1, emulator.resets(), "only the Board's own reset: the zero pulses were not read as resets");
            assertEquals(3, emulator.configuredId(), "device 3 keeps its ports");

            d.set_actuator_torque(1, 0.05f);
            d.set_actuator_torque(2, -0.05f);
            d.device_write_torques();
            d.device_read_data();
            assertEquals(0, board.idMismatches());
            assertTrue(emulator.duty(1) > 0 && emulator.duty(2) > 0, "device 3 still drives its motors");
        } finally {
            board.close();
        }
    }

    @Test
    void afterAResetIdZeroDrivesTheMotorsAndAnEncoderNeverSetUpFaultsTheBoard() throws Exception {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        Transport link = emulator.connect();
        Board board = new Board(link);
        try {
            Device d = new Device((byte) 3, board);
            HaplyPreset.HAPLY_2018.configure(d);
            d.device_set_parameters();
            board.transmit((byte) 0, (byte) 0, null, null);   // reset: every slot is free again, the objects stay
            board.transmit((byte) 2, (byte) 0, new byte[14], new float[] {0.06f, 0.03f});
            assertEquals(1 + 4 * (5 + 2), link.available(), "5 analog slots and the 2 encoders set up before");
            assertEquals(firmwareDuty(0.06f), emulator.duty(1), "id 0 drives the free motor on port 1");
            assertEquals(firmwareDuty(0.03f), emulator.duty(2));
            assertFalse(emulator.hasFaulted());
        } finally {
            board.close();
        }

        BoardEmulator fresh = new BoardEmulator(HaplyPreset.HAPLY_2018);
        Transport link2 = fresh.connect();
        Board raw = new Board(link2);
        try {
            raw.transmit((byte) 2, (byte) 0, new byte[14], new float[] {0f, 0f});
            assertTrue(fresh.hasFaulted(), "an encoder never set up is a null pointer in the firmware");
            assertEquals(0, link2.available(), "a faulted board answers nothing");
        } finally {
            raw.close();
        }
    }
}
