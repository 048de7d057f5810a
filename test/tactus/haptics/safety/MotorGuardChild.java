package tactus.haptics.safety;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import tactus.haptics.AvatarLink;
import tactus.haptics.Board;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.HapticLoop;

/**
 * A program for {@link MotorGuardTest} (not a test): a hAPI-style sketch without a window. It opens a board
 * on the given port, sets up device 5 with the 2018 preset, pushes with a constant force from a
 * {@code ScheduledExecutorService} at 1 kHz, prints READY, then ends as told on standard input:
 * {@code halt} ({@code Runtime.halt}), {@code exit} ({@code System.exit}, shutdown hooks run), {@code close}
 * (the sketch closes the board, then {@code System.exit}); anything else, or nothing, keeps it running (to
 * be ended from outside: the Stop button over JDWP, SIGKILL, SIGTERM). {@code stats} prints the board's counters
 * on a line starting with STATS. A thread calls {@link #draw(int)} every 16 ms, as Processing's animation thread
 * calls a sketch's draw(), for a debugger's breakpoint.
 */
public final class MotorGuardChild {
    private MotorGuardChild() {
    }

    /**
     * args[0]: the port; args[1]: "noguard" to turn the motor guard off with {@link Board#setMotorGuard}, or "loop"
     * to push from a {@link HapticLoop} instead of a ScheduledExecutorService.
     */
    public static void main(String[] args) throws Exception {
        if (args.length > 1 && args[1].equals("noguard")) {
            Board.setMotorGuard(false);
        }
        Board board = new Board(args[0], 0);
        Device device = new Device((byte) 5, board);
        HaplyPreset.HAPLY_2018.configure(device);
        device.device_set_parameters();
        boolean withLoop = args.length > 1 && args[1].equals("loop");
        ScheduledExecutorService haptics = Executors.newSingleThreadScheduledExecutor();
        HapticLoop loop = null;
        if (withLoop) {
            // a HapticLoop at 1 kHz rendering a constant force (2 N at the handle) against the emulator's hand
            loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), new ConstantForce(0.012, 0.016));
            loop.start();
        } else {
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
        }
        Thread draw = new Thread(() -> {
            for (int frame = 0; ; frame++) {
                draw(frame);
                try {
                    Thread.sleep(16);
                } catch (InterruptedException e) {
                    return;
                }
            }
        }, "Animation Thread");
        draw.setDaemon(true);
        draw.start();
        Thread.sleep(200);
        System.out.println("READY");
        System.out.flush();
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        String line;
        while ((line = in.readLine()) != null) {
            if ("halt".equals(line)) {
                Runtime.getRuntime().halt(0);
            } else if ("exit".equals(line)) {
                System.exit(0);
            } else if ("close".equals(line)) {
                if (loop != null) {
                    loop.stop();
                }
                haptics.shutdown();
                haptics.awaitTermination(1, TimeUnit.SECONDS);
                board.close();
                System.exit(0);
            } else if ("stats".equals(line)) {
                System.out.println("STATS unexpected=" + board.unexpectedBytes() + " mismatches=" + board.idMismatches()
                        + " implausible=" + board.implausibleFrames() + " zeroings=" + board.guardZeroings()
                        + " trips=" + board.torqueWatchdogTrips() + " closed=" + board.isClosed()
                        + (loop == null ? "" : " loop " + (loop.isRunning() ? "running" : "stopped: " + loop.failure())));
                System.out.flush();
            }
        }
        Thread.sleep(Long.MAX_VALUE);
    }

    /** What a sketch's draw() would be: called about 60 times a second on its own thread (a breakpoint goes here). */
    static int draw(int frame) {
        return frame * 31 + 7;
    }

    /** An avatar whose force is constant (model units). */
    private static final class ConstantForce implements AvatarLink {
        private final double fx;
        private final double fy;

        ConstantForce(double fx, double fy) {
            this.fx = fx;
            this.fy = fy;
        }

        @Override
        public void setTarget(double x, double y, double z) {
            // the force does not depend on the position
        }

        @Override
        public void takeForce(double[] out) {
            out[0] = fx;
            out[1] = fy;
            out[2] = 0;
        }

        @Override
        public void step(int n) {
            // nothing to step
        }
    }
}
