package tactus.haptics.safety;

import java.awt.Component;
import java.awt.EventQueue;
import java.awt.Window;
import java.awt.event.WindowEvent;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import javax.swing.SwingUtilities;
import processing.core.PApplet;
import tactus.haptics.Board;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;

/**
 * A program for {@link MotorGuardSketchTest} (not a test): a Processing sketch with a window (run it under
 * Xvfb) that opens a board with hAPI's {@code new Board(this, port, 0)}, pushes with a constant force from a
 * {@code ScheduledExecutorService} at 1 kHz, prints READY, then ends as told on standard input: {@code exit}
 * calls {@link PApplet#exit()}; {@code close} sends the sketch's window the WINDOW_CLOSING event that a
 * window manager's close button makes.
 */
public class MotorGuardSketchChild extends PApplet {
    private static String port;
    private Board board;

    /** args[0]: the port. */
    public static void main(String[] args) {
        port = args[0];
        PApplet.runSketch(new String[] {MotorGuardSketchChild.class.getName()}, new MotorGuardSketchChild());
    }

    @Override
    public void settings() {
        size(200, 100);
    }

    @Override
    public void setup() {
        board = new Board(this, port, 0);
        Device device = new Device((byte) 5, board);
        HaplyPreset.HAPLY_2018.configure(device);
        device.device_set_parameters();
        ScheduledExecutorService haptics = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "haptics");
            t.setDaemon(true);
            return t;
        });
        haptics.scheduleAtFixedRate(() -> {
            try {
                if (board.data_available()) {
                    device.device_read_data();
                }
                device.set_actuator_torque(1, 0.08f);
                device.set_actuator_torque(2, -0.08f);
                device.device_write_torques();
            } catch (RuntimeException e) {
                e.printStackTrace();
            }
        }, 1, 1, TimeUnit.MILLISECONDS);
        Thread commands = new Thread(this::obey, "commands");
        commands.setDaemon(true);
        commands.start();
    }

    @Override
    public void draw() {
        background(frameCount % 255);
    }

    private void obey() {
        try {
            Thread.sleep(200);
            System.out.println("READY");
            System.out.flush();
            BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
            String line = in.readLine();
            if ("exit".equals(line)) {
                exit();
            } else if ("close".equals(line)) {
                EventQueue.invokeLater(() -> {
                    Window w = SwingUtilities.getWindowAncestor((Component) getSurface().getNative());
                    w.dispatchEvent(new WindowEvent(w, WindowEvent.WINDOW_CLOSING));
                });
            }
        } catch (Exception e) {
            e.printStackTrace();
        }
    }
}
