package tactus.haptics.emulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.haptics.Board;
import tactus.haptics.BoardModel;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.pantograph.PantographKinematics;

/** The emulated linkage obeys the motors: a spring-held handle pushed by J^T F settles at F / k. */
class EmulatedLinkageTest {

    private static double[] settle(HaplyPreset preset, double fx, double fy, double k) {
        BoardEmulator emulator = new BoardEmulator(preset);
        emulator.setLockstep(0.001);
        double x0 = emulator.x();
        double y0 = emulator.y() + 0.03;
        emulator.setHand(Hand.spring(x0, y0, k, 2));
        try (Board board = new Board(emulator.connect())) {
            Device d = new Device((byte) 7, board);
            preset.configure(d);
            d.device_set_parameters();
            PantographKinematics kin = preset.newKinematics();
            double[] tau = new double[2];
            for (int i = 0; i < 3000; i++) {     // 3 s: the handle settles (k/m: ~ 8 Hz, damped)
                d.device_read_data();
                kin.forward(Math.toRadians(d.angle(1)), Math.toRadians(d.angle(2)));
                kin.torques(fx, fy, 1.0, tau);
                d.set_actuator_torque(1, (float) tau[0]);
                d.set_actuator_torque(2, (float) tau[1]);
                d.device_write_torques();
            }
            return new double[] {emulator.x() - x0, emulator.y() - y0};
        }
    }

    @Test
    void constantForceDisplacesASpringHeldHandleByForceOverStiffness() {
        double k = 100;
        for (HaplyPreset p : HaplyPreset.values()) {
            double[] d = settle(p, 0.5, -0.3, k);
            assertEquals(0.5 / k, d[0], 0.05 * 0.5 / k, p + " x");
            assertEquals(-0.3 / k, d[1], 0.05 * 0.5 / k, p + " y");
        }
    }

    @Test
    void noForceLeavesTheHandleOnTheHandsTarget() {
        double[] d = settle(HaplyPreset.HAPLY_2018, 0, 0, 100);
        assertEquals(0, d[0], 1e-5);
        assertEquals(0, d[1], 1e-5);
    }

    @Test
    void devKitFirmwareInvertsMotorPort2() {
        for (BoardModel model : new BoardModel[] {BoardModel.M0, BoardModel.DEV_KIT}) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018, model);
            try (Board board = new Board(emulator.connect(), model)) {
                Device d = new Device((byte) 3, board);
                HaplyPreset.HAPLY_2018.configure(d);
                d.device_set_parameters();
                d.set_actuator_torque(1, 0.05f);
                d.set_actuator_torque(2, 0.05f);
                d.device_write_torques();
                assertTrue(emulator.motorTorque(1) > 0, model + " port 1");
                assertEquals(model == BoardModel.DEV_KIT, emulator.motorTorque(2) < 0, model + " port 2");
            }
        }
    }
}
