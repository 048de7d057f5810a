package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;
import tactus.haptics.emulator.BoardEmulator;

/** Bad configuration is refused with an exception naming the value, before anything is sent. */
class DeviceValidationTest {
    private BoardEmulator emulator;
    private RecordingTransport link;
    private Board board;

    @BeforeEach
    void open() {
        emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        link = new RecordingTransport(emulator.connect());
        board = new Board(link);
    }

    @AfterEach
    void close() {
        board.close();
    }

    private void refused(Class<? extends Throwable> type, String mention, Executable call) {
        int before = link.writes.size();
        Throwable t = assertThrows(type, call);
        assertTrue(t.getMessage().contains(mention), "message should name " + mention + ": " + t.getMessage());
        assertEquals(before, link.writes.size(), "nothing may be sent");
    }

    @Test
    void refusesBadValuesAndSendsNothing() {
        assertEquals(1, link.writes.size(), "only the reset of the Board constructor");
        refused(IllegalArgumentException.class, "got 0", () -> new Device((byte) 0, board));
        Device d = new Device((byte) 3, board);
        refused(IllegalArgumentException.class, "got 3", () -> d.add_actuator(1, 0, 3));    // M0 has ports 1-2
        refused(IllegalArgumentException.class, "got 0", () -> d.add_actuator(1, 0, 0));
        refused(IllegalArgumentException.class, "got 5", () -> d.add_actuator(5, 0, 1));
        refused(IllegalArgumentException.class, "got 2", () -> d.add_actuator(1, 2, 1));
        refused(IllegalArgumentException.class, "got 0.0", () -> d.add_encoder(1, 0, 180, 0, 1));
        refused(IllegalArgumentException.class, "got NaN", () -> d.add_encoder(1, 0, 180, Float.NaN, 1));
        refused(IllegalArgumentException.class, "got Infinity", () -> d.add_encoder(1, 0, Float.POSITIVE_INFINITY, 13824, 1));
        refused(IllegalArgumentException.class, "got 4", () -> d.add_encoder(1, 0, 180, 13824, 4));
        refused(IllegalArgumentException.class, "\"A6\"", () -> d.add_analog_sensor("A6"));   // the M0 drops A6+
        refused(IllegalArgumentException.class, "\"A5\"", () -> d.add_analog_sensor("A5"));   // and overruns with A5
        refused(IllegalArgumentException.class, "\"B1\"", () -> d.add_analog_sensor("B1"));
        refused(IllegalArgumentException.class, "got 14", () -> d.add_pwm_pin(14));
        d.add_actuator(1, 0, 1);
        refused(IllegalArgumentException.class, "port 1", () -> d.add_actuator(2, 0, 1));
        refused(IllegalStateException.class, "device_set_parameters", d::device_write_torques);
        refused(IllegalStateException.class, "device_set_parameters", d::device_read_request);
        refused(IllegalStateException.class, "set_mechanism", () -> d.get_device_position(new float[] {0, 0}));
        assertEquals(0, emulator.setups());
    }

    @Test
    void refusesCcwOnALonePort2BecauseTheFirmwareWouldPutItOnPort1() {
        Device d = new Device((byte) 3, board);
        d.add_actuator(1, 1, 2);
        refused(IllegalArgumentException.class, "port 2", d::device_set_parameters);
        assertEquals(0, emulator.setups());
    }

    @Test
    void setupIsSentOnceAndTheConfigurationIsFrozenAfterIt() {
        Device d = new Device((byte) 3, board);
        HaplyPreset.HAPLY_2018.configure(d);
        d.device_set_parameters();
        assertEquals(1, emulator.setups());
        assertEquals(26, link.last().length);
        refused(IllegalStateException.class, "re-home", d::device_set_parameters);
        refused(IllegalStateException.class, "already sent", () -> d.add_encoder(3, 0, 0, 13824, 1));
        refused(IllegalStateException.class, "already set up", () -> new Device((byte) 3, board).device_set_parameters());
        assertEquals(1, emulator.setups());
    }

    @Test
    void aSecondDeviceOnTheSamePortsIsRefusedNamingBothIdsAndThePorts() {
        Device first = new Device((byte) 3, board);
        HaplyPreset.HAPLY_2018.configure(first);
        first.device_set_parameters();
        Device second = new Device((byte) 7, board);
        second.add_actuator(1, 0, 1);
        second.add_encoder(1, 0, 180, 13824, 1);
        IllegalStateException e = assertThrows(IllegalStateException.class, second::device_set_parameters);
        String m = e.getMessage();
        assertTrue(m.contains("id 3") && m.contains("id 7"), m);
        assertTrue(m.contains("motor ports 1") && m.contains("encoder ports 1"), m);
        assertTrue(m.contains("emulator"), "names the board's port: " + m);
        assertEquals(1, emulator.setups(), "no second setup was sent");
        assertEquals(3, emulator.configuredId(), "the ports stay with id 3");
        // the first device keeps working
        first.set_actuator_torque(1, 0.05f);
        first.device_write_torques();
        first.device_read_data();
        assertEquals(0, board.idMismatches());
        assertTrue(emulator.duty(1) > 0);
    }

    @Test
    void aSecondDeviceOnOtherPortsIsRefusedTooBecauseASetupClearsEveryAssignment() {
        Device first = new Device((byte) 3, board);
        first.add_actuator(1, 0, 1);
        first.device_set_parameters();
        Device second = new Device((byte) 7, board);
        second.add_actuator(1, 0, 2);
        refused(IllegalStateException.class, "clear its assignments", second::device_set_parameters);
        assertEquals(1, emulator.setups());
    }
}
