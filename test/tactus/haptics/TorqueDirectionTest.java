package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.pantograph.PantographKinematics;

/** Torques above the firmware's 0.123 N m clip never turn the force: refused in the loop, scaled together in Device. */
class TorqueDirectionTest {

    @Test
    void aLoopLimitAboveTheFirmwaresClipIsRefusedNamingBoth() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        Board board = new Board(emulator.connect());
        try {
            Device device = new Device((byte) 3, board);
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), new NoForceAvatar());
            for (double nm : new double[] {0.124, 0.2, 0.5}) {
                IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> loop.setTorqueLimit(nm));
                assertTrue(e.getMessage().contains(Double.toString(nm)) && e.getMessage().contains("0.123"), e.getMessage());
            }
            loop.setTorqueLimit(0.123);   // the clip itself is fine
            loop.setTorqueLimit(0.05);
        } finally {
            board.close();
        }
    }

    @Test
    void torquesAboveTheClipAreScaledTogetherSoTheForceKeepsItsDirection() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        emulator.setLockstep(0.001);
        Board board = new Board(emulator.connect());
        try {
            Device device = new Device((byte) 3, board);
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            PantographKinematics kin = HaplyPreset.HAPLY_2018.newKinematics();
            device.device_read_request();
            device.device_read_data();
            assertTrue(kin.forward(Math.toRadians(device.angle(1)), Math.toRadians(device.angle(2))));
            double[] tau = new double[2];
            double[] f = new double[2];
            double worst = 0;
            for (int k = 0; k < 36; k++) {   // a force of 15 N in every direction: far above the clip
                double a = Math.toRadians(10 * k);
                kin.torques(15 * Math.cos(a), 15 * Math.sin(a), 1, tau);
                device.set_actuator_torque(1, (float) tau[0]);
                device.set_actuator_torque(2, (float) tau[1]);
                device.device_write_torques();
                device.device_read_data();
                kin.forceFromTorques(emulator.motorTorque(1), emulator.motorTorque(2), f);
                double turn = Math.abs(Math.toDegrees(Math.atan2(
                        Math.cos(a) * f[1] - Math.sin(a) * f[0], Math.cos(a) * f[0] + Math.sin(a) * f[1])));
                worst = Math.max(worst, turn);
                double biggest = Math.max(Math.abs(emulator.motorTorque(1)), Math.abs(emulator.motorTorque(2)));
                assertEquals(0.123, biggest, 0.123 / 1023 + 1e-9, "the larger torque sits at the clip");
            }
            System.out.println("TorqueDirectionTest: largest turn of the rendered force " + worst + " degrees");
            assertTrue(worst < 1.0, "the force turned by " + worst + " degrees");
            assertEquals(36, device.scaledWrites());
        } finally {
            board.close();
        }
    }
}
