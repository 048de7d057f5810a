package tactus.haptics.inverse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static tactus.haptics.inverse.Inverse3LoopTest.await;

import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import tactus.haptics.HapticLoop;
import tactus.haptics.emulator.Hand3D;
import tactus.haptics.emulator.InverseServiceEmulator;
import tactus.haptics.emulator.SimulatedInverse3;

/**
 * A service that stops and comes back on the same port: a reconnecting Inverse3Device keeps the loop running
 * without force while the service is away (the avatar holds), reconnects with a bounded back-off, ramps the force
 * back in, and gives up with a message when the service stays away; never a hang.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class InverseReconnectTest {

    private static InverseServiceEmulator emulator(int port, double[] where) {
        InverseServiceEmulator emu = InverseServiceEmulator.start(port);
        emu.device().setHand(Hand3D.scripted((t, out) -> System.arraycopy(where, 0, out, 0, 3)));
        emu.setRecording(true);
        return emu;
    }

    @Test
    void aRestartedServiceIsReachedAgainAndTheForceRampsBackIn() {
        double[] home = SimulatedInverse3.HOME;
        InverseServiceEmulator first = emulator(0, home);
        int port = first.port();
        try (Inverse3Device dev = Inverse3Device.open(first.uri(), 10_000)) {
            dev.setReconnect(10_000);
            HapticLoop loop = new HapticLoop(dev, new Inverse3LoopTest.ConstantAvatar(0.5, 0, 0));
            loop.useRealUnits();
            loop.start();
            await(() -> loop.ticks() > 300, 20_000, "300 ticks: " + loop.failure());
            double[] before = new double[3];
            loop.devicePosition(before);
            first.close();                                   // the service stops (a closing handshake, code 1001)
            await(dev::isReconnecting, 5_000, "the device notices and reconnects");
            long ticks = loop.ticks();
            await(() -> loop.ticks() > ticks + 200, 10_000, "the loop keeps running while the service is away: "
                    + loop.failure());
            assertTrue(loop.isRunning(), String.valueOf(loop.failure()));
            assertTrue(dev.status().startsWith("reconnecting to the Haply Inverse Service"), dev.status());
            assertTrue(dev.forcesHeld() > 0, "nothing is sent while the service is away");
            double[] held = new double[3];
            loop.devicePosition(held);
            for (int i = 0; i < 3; i++) {
                assertEquals(before[i], held[i], 1e-3, "the avatar holds at the last position seen, axis " + i);
            }
            try (InverseServiceEmulator second = emulator(port, home)) {   // the service is back, same port
                await(() -> dev.reconnections() == 1, 10_000, "reconnected: " + dev.status());
                await(() -> second.receivedForces().size() > 300, 10_000, "forces reach the new service");
                List<double[]> got = second.receivedForces();
                assertTrue(got.get(0)[0] < 0.5 * 0.5, "the force ramps back in: first " + got.get(0)[0]);
                assertEquals(0.5, got.get(got.size() - 1)[0], 1e-9, "then the full force");
                assertTrue(loop.isRunning(), String.valueOf(loop.failure()));
                assertTrue(dev.status().contains("reconnected 1 time"), dev.status());
                loop.stop();
                await(() -> {
                    List<double[]> end = second.receivedForces();
                    return end.get(end.size() - 1)[0] == 0;
                }, 5_000, "stop() sends zero force to the new service");
            }
        } finally {
            first.close();
        }
    }

    @Test
    void aServiceThatStaysAwayStopsTheLoopWithAMessage() {
        InverseServiceEmulator emu = emulator(0, SimulatedInverse3.HOME);
        try (Inverse3Device dev = Inverse3Device.open(emu.uri(), 10_000)) {
            dev.setReconnect(600);
            HapticLoop loop = new HapticLoop(dev, new Inverse3LoopTest.ConstantAvatar(0.5, 0, 0));
            loop.useRealUnits();
            loop.start();
            await(() -> loop.ticks() > 200, 20_000, "200 ticks: " + loop.failure());
            long t0 = System.nanoTime();
            emu.dropConnections();
            emu.close();
            await(() -> !loop.isRunning(), 10_000, "the loop stops once reconnecting gives up");
            long ms = (System.nanoTime() - t0) / 1_000_000L;
            assertTrue(ms >= 500, "it tried for its 600 ms first: " + ms + " ms");
            assertTrue(loop.failure().contains("did not come back within 0.6 s"), loop.failure());
        } finally {
            emu.close();
        }
    }
}
