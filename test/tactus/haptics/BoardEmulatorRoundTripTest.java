package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;
import tactus.haptics.pantograph.PantographKinematics;

/** The device layer against the in-process emulator: the hAPI flow, the firmware's arithmetic, and the fixes. */
class BoardEmulatorRoundTripTest {

    private static final class Rig implements AutoCloseable {
        final BoardEmulator emulator;
        final RecordingTransport link;
        final Board board;
        final Device device;

        Rig(HaplyPreset preset, byte id) {
            emulator = new BoardEmulator(preset);
            emulator.setLockstep(0.001);
            link = new RecordingTransport(emulator.connect());
            board = new Board(link);
            device = new Device(id, board);
            preset.configure(device);
            device.device_set_parameters();
        }

        @Override
        public void close() {
            board.close();
        }
    }

    @Test
    void helloWallFlowReadsTheCalibrationPoseAfterAWrite() {
        try (Rig r = new Rig(HaplyPreset.HAPLY_2018, (byte) 3)) {
            assertFalse(r.board.data_available());
            r.device.set_device_torques(new float[] {0f, 0f, 0f});
            r.device.device_write_torques();
            assertTrue(r.board.data_available(), "the reply must be there after the write");
            r.device.device_read_data();
            // 180 and 0 degrees are exact at 13824 counts
            assertArrayEquals(new float[] {180f, 0f}, r.device.get_device_angles());
            float[] pos = r.device.get_device_position(new float[] {180f, 0f, 0f});
            PantographKinematics k = HaplyPreset.HAPLY_2018.newKinematics();
            k.forward(Math.PI, 0);
            assertEquals(k.x(), pos[0], 1e-7);
            assertEquals(k.y(), pos[1], 1e-7);
            assertEquals(r.emulator.x(), pos[0], 1e-4);
            assertEquals(r.emulator.y(), pos[1], 1e-4);
            assertEquals(1, r.board.framesRead());
        }
    }

    @Test
    void encoderHomeAnglesAreTruncatedLikeTheFirmware() {
        try (Rig r = new Rig(HaplyPreset.TWO_DIY_V3, (byte) 5)) {
            r.device.device_read_request();
            r.device.device_read_data();
            // M0: half-rate counting, step 720/res; preset count truncated: trunc(168*2440/360) = 1138
            float a1 = 360f * (int) (168f * 2440f / 360f) / 2440f;
            float a2 = 360f * (int) (12f * 2440f / 360f) / 2440f;
            assertArrayEquals(new float[] {a1, a2}, r.device.get_device_angles());
            assertEquals(167.90164f, a1, 1e-4f);
            assertEquals(11.95082f, a2, 1e-4f);
        }
    }

    @Test
    void encodersAreQuantisedAtTheConfiguredResolution() {
        try (Rig r = new Rig(HaplyPreset.HAPLY_2018, (byte) 3)) {
            double[] target = {0.0, 0.08};
            r.emulator.setHand(Hand.scripted((t, out) -> {
                out[0] = target[0];
                out[1] = target[1];
            }));
            r.device.device_read_request();
            r.device.device_read_data();
            float[] a = r.device.get_device_angles();
            double step = 720.0 / 13824;   // degrees per count on the M0
            for (int j = 0; j < 2; j++) {
                double phys = r.emulator.jointDegrees(j + 1);
                assertTrue(Math.abs(a[j] - phys) <= step + 1e-4, "angle " + a[j] + " vs joint " + phys);
                double counts = a[j] / step;
                assertEquals(Math.rint(counts), counts, 1e-3, "a whole number of counts");
            }
            float[] pos = r.device.get_device_position(a);
            assertEquals(0.0, pos[0], 2e-4);
            assertEquals(0.08, pos[1], 2e-4);
        }
    }

    @Test
    void torqueBecomesPwmTheFirmwareWay() {
        try (Rig r = new Rig(HaplyPreset.HAPLY_2018, (byte) 3)) {
            float[][] cases = {{0.05f, -0.05f}, {0.2f, -1f}, {1e-4f, 0f}, {-0.123f, 0.0615f}};
            for (float[] c : cases) {
                r.device.set_actuator_torque(1, c[0]);
                r.device.set_actuator_torque(2, c[1]);
                r.device.device_write_torques();
                r.device.device_read_data();
                // above the clip the device scales both torques together (the direction holds)
                float max = Math.max(Math.abs(c[0]), Math.abs(c[1]));
                float k = max > 0.123f ? 0.123f / max : 1f;
                for (int j = 0; j < 2; j++) {
                    float tau = c[j] * k;
                    int duty = (int) ((float) (1023 * Math.min(Math.abs(tau), 0.123f)) / 0.123);
                    assertEquals(duty, r.emulator.duty(j + 1), "duty for " + tau);
                    // rotation CW: tau > 0 drives the pin LOW, tau <= 0 HIGH
                    assertEquals(!(tau > 0), r.emulator.directionPinHigh(j + 1), "pin for " + tau);
                    assertEquals(Math.signum(tau) * duty * 0.123 / 1023, r.emulator.motorTorque(j + 1), 1e-12);
                    if (Math.abs(tau) < 0.123 / 1023) {
                        assertEquals(0, r.emulator.duty(j + 1), "below one duty step");
                    }
                }
            }
        }
    }

    @Test
    void ccwWiringStillPushesTheRightWay() {
        // 2DIY v3: every motor CCW and the joints cross-wired (joint 1 on port 2)
        try (Rig r = new Rig(HaplyPreset.TWO_DIY_V3, (byte) 5)) {
            r.device.set_actuator_torque(1, 0.06f);
            r.device.set_actuator_torque(2, -0.03f);
            r.device.device_write_torques();
            assertTrue(r.emulator.directionPinHigh(2), "CCW inverts: tau > 0 drives the pin HIGH");
            assertEquals(0.06, r.emulator.motorTorque(1), 0.123 / 1023);
            assertEquals(-0.03, r.emulator.motorTorque(2), 0.123 / 1023);
        }
    }

    @Test
    void aReadKeepsTheNewestFrame() {
        try (Rig r = new Rig(HaplyPreset.HAPLY_2018, (byte) 3)) {
            // the hand moves 1 mm in x per write (lockstep: 1 ms per write)
            r.emulator.setHand(Hand.scripted((t, out) -> {
                out[0] = Math.round(t * 1000) * 0.001 - 0.01;
                out[1] = 0.08;
            }));
            for (int i = 0; i < 5; i++) {
                r.device.device_read_request();   // five ticks whose replies were not read
            }
            r.device.device_read_data();
            assertEquals(4, r.board.framesSkipped());
            float[] pos = r.device.get_device_position(r.device.get_device_angles());
            assertEquals(r.emulator.x(), pos[0], 2e-4, "the newest position, not the first one");
            assertEquals(-0.005, pos[0], 2e-4);
            assertFalse(r.board.data_available());
        }
    }

    @Test
    void eachCommandGoesOutInOneWrite() {
        try (Rig r = new Rig(HaplyPreset.HAPLY_2018, (byte) 3)) {
            r.device.device_write_torques();
            r.device.device_read_data();
            assertEquals(3, r.link.writes.size());
            assertEquals(2, r.link.writes.get(0).length);    // reset
            assertEquals(26, r.link.writes.get(1).length);   // setup
            assertEquals(10, r.link.writes.get(2).length);   // write
            assertEquals(0, r.emulator.lateBytes());
            assertEquals(0, r.emulator.unknownBytes());
        }
    }

    @Test
    void closeSendsZeroTorquesBecauseAResetDoesNotStopTheMotors() {
        try (Rig r = new Rig(HaplyPreset.HAPLY_2018, (byte) 3)) {
            r.device.set_actuator_torque(1, 0.1f);
            r.device.device_write_torques();
            assertTrue(r.emulator.duty(1) > 0);
            // what hAPI does at exit: nothing, or a reset; the motor keeps pushing
            r.board.transmit((byte) 0, (byte) 0, null, null);
            assertTrue(r.emulator.duty(1) > 0, "a reset leaves the duty as it was");
            assertEquals(0, r.emulator.configuredId() + 1);
        }
        // a fresh rig to check close() itself
        Rig r = new Rig(HaplyPreset.HAPLY_2018, (byte) 3);
        r.device.set_actuator_torque(1, 0.1f);
        r.device.set_actuator_torque(2, -0.1f);
        r.device.device_write_torques();
        assertTrue(r.emulator.duty(1) > 0 && r.emulator.duty(2) > 0);
        long resets = r.emulator.resets();
        r.board.close();
        assertEquals(resets + 1, r.emulator.resets(), "and the board is reset");
        assertEquals(-1, r.emulator.configuredId());
        assertEquals(0, r.emulator.duty(1));
        assertEquals(0, r.emulator.duty(2));
        assertEquals(0.0, r.emulator.motorTorque(1));
        assertTrue(r.board.isClosed());
        r.board.close();   // twice is harmless
        assertThrows(HaplyLinkException.class, r.device::device_write_torques);
    }

    @Test
    void nonFiniteTorquesAreSentAsZero() {
        try (Rig r = new Rig(HaplyPreset.HAPLY_2018, (byte) 3)) {
            r.device.set_actuator_torque(1, 0.1f);
            r.device.device_write_torques();
            r.device.set_actuator_torque(1, Float.NaN);
            r.device.set_actuator_torque(2, Float.POSITIVE_INFINITY);
            r.device.device_write_torques();
            assertEquals(0, r.emulator.duty(1));
            assertEquals(0, r.emulator.duty(2));
            assertEquals(2, r.device.nonFiniteTorques());
        }
    }

    @Test
    void analogValuesComeFirstThenAnglesInPortOrder() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.TWO_DIY_V3);
        emulator.setAnalog(0, 111);
        emulator.setAnalog(1, 2222);
        emulator.setAnalog(2, 3333);
        try (Board board = new Board(emulator.connect())) {
            Device d = new Device((byte) 5, board);
            HaplyPreset.TWO_DIY_V3.configure(d);
            d.add_analog_sensor("A2");
            d.add_analog_sensor("A0");
            d.add_analog_sensor("A1");
            d.device_set_parameters();
            d.device_read_request();
            d.device_read_data();
            // in the order added; the M0 reads only A1 and A2 (A0 reports 0)
            assertArrayEquals(new float[] {3333f, 0f, 2222f}, d.get_sensor_data());
            // encoder 1 is on port 2: the reply's angles are in port order, get_device_angles in index order
            assertArrayEquals(new float[] {360f * 1138 / 2440, 360f * 81 / 2440}, d.get_device_angles());
        }
    }
}
