package tactus.haptics;

import java.util.concurrent.locks.LockSupport;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;
import tactus.haptics.emulator.PtyPair;

/**
 * Measures the haptic loop's telemetry over the pty emulator (not a test; run on demand):
 * {@code java ... tactus.haptics.HapticLoopBench SECONDS haptics|audio|audio-decoupled}. "haptics": the paper's
 * HeavyMassChain stepped by the haptic thread at 1 kHz. "audio": a 200-mass string at 44.1 kHz stepped by an
 * audio-like thread in bursts of 1024 steps per 23.2 ms, the haptic thread only moving the avatar and taking
 * the force (through the model's lock). "audio-decoupled": the same through a {@link DecoupledAvatar}.
 */
public final class HapticLoopBench {
    private HapticLoopBench() {
    }

    public static void main(String[] args) throws Exception {
        double seconds = args.length > 0 ? Double.parseDouble(args[0]) : 60;
        String mode = args.length > 1 ? args[1] : "haptics";
        boolean audio = mode.startsWith("audio");
        boolean decoupled = mode.equals("audio-decoupled");
        try (PtyPair pty = PtyPair.open()) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
            emulator.setHand(Hand.scripted((t, out) -> {
                out[0] = 0.02 * Math.sin(2 * Math.PI * 0.5 * t);
                out[1] = 0.08 + 0.01 * Math.sin(2 * Math.PI * 0.3 * t);
            }));
            emulator.serve(SerialTransport.open(pty.boardEnd(), 0));
            Board board = new Board(pty.hostEnd(), 0);
            Device device = new Device((byte) 5, board);
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            PhysicalModel pm = audio ? string() : chain();
            AvatarLink avatar = new PhysicalModelAvatar(pm, "hapticMass");
            DecoupledAvatar exchange = decoupled ? new DecoupledAvatar(avatar) : null;
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(),
                    decoupled ? exchange : avatar);
            loop.setOrigin(0, -200 * 0.08, 0);
            Thread audioThread = null;
            boolean[] stop = {false};
            if (audio) {
                loop.setMode(HapticLoop.Mode.AUDIO);
                loop.setForceGain(1);
                audioThread = new Thread(() -> {
                    long period = Math.round(1024 / 44100.0 * 1e9);
                    long next = System.nanoTime();
                    while (!stop[0]) {
                        pm.computeNSteps(1024);
                        next += period;
                        long wait = next - System.nanoTime();
                        if (wait > 0) {
                            LockSupport.parkNanos(wait);
                        }
                    }
                }, "audio-like");
                audioThread.setDaemon(true);
                audioThread.start();
            }
            loop.start();
            Thread.sleep((long) (seconds * 1000));
            HapticTelemetry t = loop.telemetry();
            stop[0] = true;
            loop.close();
            if (exchange != null) {
                exchange.close();
            }
            System.out.println(mode + " " + t);
            System.out.println("board: frames " + board.framesRead() + ", skipped " + board.framesSkipped()
                    + ", id mismatches " + board.idMismatches() + ", emulator writes " + emulator.writes()
                    + ", late bytes " + emulator.lateBytes());
            emulator.close();
        }
    }

    static PhysicalModel chain() {
        PhysicalModel pm = new PhysicalModel(1000);
        pm.addHapticInput3D("hapticMass", new Vect3D(), 10);
        for (int i = 0; i < 10; i++) {
            pm.addMass3D("m" + i, 50, new Vect3D(0.1 * (i + 1), 0, 0), new Vect3D());
        }
        for (int i = 0; i < 9; i++) {
            pm.addSpringDamper3D("k" + i, 0.1, 0.003, 0.05, "m" + i, "m" + (i + 1));
        }
        pm.addSpringDamper3D("grip", 0.1, 0.003, 0.05, "hapticMass", "m0");
        pm.init();
        return pm;
    }

    static PhysicalModel string() {
        PhysicalModel pm = new PhysicalModel(44100);
        pm.addHapticInput3D("hapticMass", new Vect3D(0, 1, 0), 30);
        pm.addGround3D("g0", new Vect3D(-1, 0, 0));
        pm.addGround3D("g1", new Vect3D(1, 0, 0));
        int n = 200;
        for (int i = 0; i < n; i++) {
            pm.addMass3D("s" + i, 1, new Vect3D(-1 + 2.0 * (i + 1) / (n + 1), 0, 0), new Vect3D());
        }
        pm.addSpringDamper3D("e0", 0, 0.1, 0.001, "g0", "s0");
        for (int i = 0; i + 1 < n; i++) {
            pm.addSpringDamper3D("e" + (i + 1), 0, 0.1, 0.001, "s" + i, "s" + (i + 1));
        }
        pm.addSpringDamper3D("e" + n, 0, 0.1, 0.001, "s" + (n - 1), "g1");
        pm.addSpringDamper3D("pluck", 0.5, 0.01, 0.001, "hapticMass", "s" + (n / 2));
        pm.init();
        return pm;
    }
}
