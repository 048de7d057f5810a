package tactus.haptics;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;

/**
 * A program for {@link ShutdownHookTest} (not a test): opens a board on the given port, drives the motors,
 * prints READY, and on "exit" from stdin ends the JVM without closing anything, as a sketch stopped
 * without dispose() would.
 */
public final class ShutdownHookChild {
    private ShutdownHookChild() {
    }

    public static void main(String[] args) throws Exception {
        Board board = new Board(args[0], 0);
        board.setTorqueWatchdogMillis(0);   // the torque is written once and held: this tests the hook alone
        Device d = new Device((byte) 3, board);
        HaplyPreset.HAPLY_2018.configure(d);
        d.device_set_parameters();
        d.set_actuator_torque(1, 0.08f);
        d.set_actuator_torque(2, -0.08f);
        d.device_write_torques();
        d.device_read_data();
        System.out.println("READY");
        System.out.flush();
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        in.readLine();
        System.exit(0);   // no close(), no dispose()
    }
}
