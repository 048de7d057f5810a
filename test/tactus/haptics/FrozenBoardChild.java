package tactus.haptics;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * A program for {@link FrozenBoardShutdownTest} (not a test): a hAPI-style sketch thread, as the hAPI examples
 * write it (data_available, device_read_data, set_device_torques, device_write_torques every millisecond on
 * a ScheduledExecutorService), on the port given as args[0]. args[1] is the board's lost-after count (reads
 * of 100 ms). Prints READY once a reply has been read, then runs until the JVM is ended from outside.
 */
public final class FrozenBoardChild {
    private FrozenBoardChild() {
    }

    public static void main(String[] args) throws Exception {
        Board haplyBoard = new Board(args[0], 0);
        haplyBoard.setLostAfterTimeouts(Integer.parseInt(args[1]));
        Device widgetOne = new Device((byte) 5, haplyBoard);
        HaplyPreset.HAPLY_2018.configure(widgetOne);
        widgetOne.device_set_parameters();
        float[] force = {0.4f, 0.3f, 0f};
        boolean[] ready = new boolean[1];
        ScheduledExecutorService scheduler = Executors.newScheduledThreadPool(1);
        scheduler.scheduleAtFixedRate(() -> {
            if (haplyBoard.data_available()) {
                widgetOne.device_read_data();
                float[] angles = widgetOne.get_device_angles();
                widgetOne.get_device_position(new float[] {angles[0], angles[1], 0f});
                widgetOne.set_device_torques(force);
                if (!ready[0]) {
                    ready[0] = true;
                    System.out.println("READY");
                    System.out.flush();
                }
            }
            widgetOne.device_write_torques();
        }, 1, 1, TimeUnit.MILLISECONDS);
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        while (in.readLine() != null) {
            // runs until killed; the non-daemon scheduler thread keeps the JVM alive as in a sketch
        }
    }
}
