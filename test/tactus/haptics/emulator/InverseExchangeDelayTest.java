package tactus.haptics.emulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.HapticLoop;
import tactus.haptics.PhysicalModelAvatar;
import tactus.haptics.WorkspaceMapping;
import tactus.haptics.inverse.Inverse3Device;
import tactus.paramSystem;

/**
 * The exchange delay of the emulated Inverse3 on its real path (the haptic loop, {@code Inverse3Device}, the
 * WebSocket, the {@link InverseServiceEmulator} in lockstep): the emulator applies each force, advances one period
 * and answers with the state it reached, so the position a tick reads is the answer to the force the previous tick
 * sent, and that force acted over exactly one tick: d = 0 ticks of delay, whenever the answer arrives within the
 * tick. The trace shows it: the force the model computed (a spring, so the force says the position it was computed
 * from) comes from the frame that answered the previous message whenever that frame arrived in time; on a loaded
 * machine a frame often comes late and the force is computed from an older one (the test prints how often).
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class InverseExchangeDelayTest {
    private static final double K = 200;
    private static final double OFFSET = 0.002;
    /** Forces left out at the start: Inverse3Device ramps its forces in over 100 ms of wall clock. */
    private static final int RAMP_FORCES = 250;

    @Test
    void aForceIsComputedFromTheFrameThatAnsweredThePreviousForceWhenItCameInTime() throws Exception {
        SimulatedInverse3 sim = new SimulatedInverse3();
        sim.setPlant(PlantParameters.cartesian3Dof().withoutFriction());
        double[] home = SimulatedInverse3.HOME;
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0, sim)) {
            emu.setLockstep(0.001);
            emu.setRecording(true);
            Inverse3Device device = Inverse3Device.open(emu.uri(), 5000);
            PhysicalModel pm = new PhysicalModel(1000, paramSystem.REAL_UNITS);
            pm.addHapticInput3D("avatar", new Vect3D(home[0], home[1], home[2]), 1);
            pm.addGround3D("anchor", new Vect3D(home[0], home[1] - 1, home[2]));
            pm.addSpringDamper3D("wall", 1 - OFFSET, K, 0, "avatar", "anchor");   // the handle moves all along
            pm.init();
            HapticLoop loop = new HapticLoop(device, new PhysicalModelAvatar(pm, "avatar"));
            loop.setWorkspaceMapping(WorkspaceMapping.identity());
            loop.setForceGain(1);
            loop.setHeapWarmup(false);
            loop.start();
            long deadline = System.nanoTime() + 30_000_000_000L;
            while (loop.isRunning() && emu.forceCommands() < RAMP_FORCES + 600 && System.nanoTime() < deadline) {
                LockSupport.parkNanos(2_000_000);
            }
            loop.stop();
            assertNull(loop.failure(), "the loop failed");
            loop.close();

            // frame 0 is the snapshot sent on connect, frame m the answer to message m; the first message is the
            // client's handshake (no force), so force i (from 0) is message i + 2 and its answer frame i + 2. The
            // force the model computed from the frame the loop read, F = -K (y - y0 + offset), says which frame that
            // was: lag = (i + 1) - j frames between the answer to the previous message and the frame used.
            List<double[]> frames = emu.sentPositions();
            List<double[]> forces = emu.receivedForces();
            assertEquals(emu.messagesReceived(), forces.size() + 1, "one handshake, then one force per message");
            assertEquals(emu.messagesReceived() + 1, frames.size(), "one frame on connect and one per message");
            int[] lags = new int[5];
            int unmatched = 0;
            int zeros = 0;
            for (int i = RAMP_FORCES; i < forces.size(); i++) {
                if (forces.get(i)[1] == 0) {
                    zeros++;   // the loop's stop sends zero force
                    continue;
                }
                double y = home[1] - OFFSET - forces.get(i)[1] / K;
                int j = nearest(frames, y);
                if (Math.abs(frames.get(j)[1] - y) > 1e-9) {
                    unmatched++;
                    continue;
                }
                int lag = i + 1 - j;
                assertTrue(lag >= 0, "force " + i + " was computed from frame " + j + ", which it precedes");
                lags[Math.min(lag, 4)]++;
            }
            System.out.println("InverseExchangeDelayTest: forces computed from the frame just answered (lag 0), 1, 2, 3, "
                    + "4+ frames before: " + java.util.Arrays.toString(lags) + ", unmatched " + unmatched + ", zero " + zeros + " of "
                    + (forces.size() - RAMP_FORCES));
            assertEquals(0, unmatched, "every force comes from a frame the emulator sent");
            assertTrue(zeros <= 8, zeros + " zero forces: only the stop's (zeroForce, close)");
            // d = 0 whenever the answer is in time: then the force computed from a frame is the very next message
            assertTrue(lags[0] > 0, "no force was computed from the frame that answered the previous message");
            double moved = Math.abs(frames.get(frames.size() - 1)[1] - frames.get(0)[1]);
            assertTrue(moved > 1e-4, "the handle moved " + moved + " m");
        }
    }

    private static int nearest(List<double[]> frames, double y) {
        int best = 0;
        for (int j = 1; j < frames.size(); j++) {
            if (Math.abs(frames.get(j)[1] - y) < Math.abs(frames.get(best)[1] - y)) {
                best = j;
            }
        }
        return best;
    }
}
