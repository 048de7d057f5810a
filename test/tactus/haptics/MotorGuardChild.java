package tactus.haptics;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * A program for {@link MotorGuardTest} (not a test): a hAPI-style sketch without a window. It opens a board
 * on the given port, sets up device 5 with the 2018 preset, pushes with a constant force from a
 * {@code ScheduledExecutorService} at 1 kHz, prints READY, then ends as told on standard input:
 * {@code halt} ({@code Runtime.halt}), {@code exit} ({@code System.exit}, shutdown hooks run), {@code close}
 * (the sketch closes the board, then {@code System.exit}); anything else, or nothing, keeps it running (to
 * be ended from outside: the Stop button over JDWP, SIGKILL, SIGTERM).
 */
public final class MotorGuardChild {
    private MotorGuardChild() {
    }

    /** args[0]: the port; args[1]: "noguard" to turn the motor guard off with {@link Board#setMotorGuard}. */
    public static void main(String[] args) throws Exception {
        if (args.length > 1 && args[1].equals("noguard")) {
            Board.setMotorGuard(false);
        }
        Board board = new Board(args[0], 0);
        Device device = new Device((byte) 5, board);
        HaplyPreset.HAPLY_2018.configure(device);
        device.device_set_parameters();
        ScheduledExecutorService haptics = Executors.newSingleThreadScheduledExecutor();
        haptics.scheduleAtFixedRate(() -> {
            try {
                if (board.data_available()) {
                    device.device_read_data();
                }
                device.set_actuator_torque(1, 0.08f);   // a constant force: duty 665 on each motor
                device.set_actuator_torque(2, -0.08f);
                device.device_write_torques();
            } catch (RuntimeException e) {
                e.printStackTrace();
            }
        }, 1, 1, TimeUnit.MILLISECONDS);
        Thread.sleep(200);
        System.out.println("READY");
        System.out.flush();
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        String line = in.readLine();
        if ("halt".equals(line)) {
            Runtime.getRuntime().halt(0);
        } else if ("exit".equals(line)) {
            System.exit(0);
        } else if ("close".equals(line)) {
            haptics.shutdown();
            haptics.awaitTermination(1, TimeUnit.SECONDS);
            board.close();
            System.exit(0);
        }
        Thread.sleep(Long.MAX_VALUE);
    }
}
