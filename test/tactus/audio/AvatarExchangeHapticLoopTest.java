package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import tactus.haptics.AvatarLink;
import tactus.haptics.HaplyPreset;
import tactus.haptics.HapticLoop;
import tactus.haptics.HapticSession;
import tactus.haptics.loop.DecoupledAvatar;

/**
 * The glue of the audio-haptic examples (PluckedString, MultipleStrings, HapticAudioTemplate): a HapticSession's
 * loop in AUDIO mode over an AvatarExchange in SUM mode, through an AvatarLink that returns the steps each take
 * covers. The audio side adds one force per step in bursts, as Minim computes a buffer; every tick must render
 * exactly the mean force per step, between the bursts too, and the handle's position must reach the audio side.
 */
class AvatarExchangeHapticLoopTest {

    private static AvatarLink over(AvatarExchange exchange) {
        return new ExchangeAvatarLink(exchange);
    }

    @Test
    void theLoopRendersTheExactMeanForcePerAudioStep() throws Exception {
        // the same force every step: any take whose sum and step count disagree (a step counted but not summed,
        // or the reverse) renders (n +- 1) / n of it, at least 1/1024 off; a take with no step keeps the mean
        for (boolean decoupled : new boolean[] {false, true}) {
            AvatarExchange exchange = new AvatarExchange(AvatarExchange.ForceMode.SUM);
            try (HapticSession s = HapticSession.openEmulated(null, HaplyPreset.HAPLY_2018)) {
                // ExchangeAvatarLink never waits, so the loop calls it directly; the helper-thread path is
                // exercised by wrapping it by hand
                AvatarLink link = decoupled ? new tactus.haptics.loop.DecoupledAvatar(over(exchange)) : over(exchange);
                HapticLoop loop = s.attach(link);
                loop.setMode(HapticLoop.Mode.AUDIO);
                assertEquals(decoupled, loop.isDecoupled(), "helper thread in use");
                loop.setPositionGain(1);
                loop.setOrigin(0, 0, 0);
                loop.setMirrorX(false);
                loop.setForceGain(1);
                loop.start();
                // the loop asks for real-time scheduling before its first tick (a chrt process, seconds under load):
                // the force is read only once the loop has ticked, or it would still show the zero it started with
                long started = System.nanoTime() + 20_000_000_000L;
                while (loop.ticks() < 20 && loop.isRunning() && System.nanoTime() < started) {
                    LockSupport.parkNanos(1_000_000);
                }
                assertTrue(loop.ticks() >= 20, () -> "the loop did not start ticking: " + loop.failure());
                boolean[] stop = {false};
                double[] seen = new double[3];
                boolean[] got = {false};
                Thread audio = new Thread(() -> {
                    while (!stop[0]) {
                        for (int i = 0; i < 1024; i++) {
                            if (exchange.readPosition(seen)) {
                                got[0] = true;
                            }
                            exchange.addForce(0.05, -0.025, 0);
                        }
                        LockSupport.parkNanos(23_200_000L);
                    }
                });
                audio.start();
                try {
                    long deadline = System.nanoTime() + 10_000_000_000L;
                    while (exchange.audioSteps() < 4096 && System.nanoTime() < deadline) {
                        LockSupport.parkNanos(1_000_000);
                    }
                    LockSupport.parkNanos(5_000_000);
                    double[] f = new double[2];
                    for (int k = 0; k < 500; k++) {
                        loop.deviceForce(f);
                        String at = "decoupled " + decoupled + ", tick sample " + k;
                        assertEquals(0.05, f[0], 1e-9, at);
                        assertEquals(-0.025, f[1], 1e-9, at);
                        LockSupport.parkNanos(1_000_000);
                    }
                    assertTrue(loop.isRunning(), () -> "loop stopped: " + loop.failure());
                    assertEquals(0, loop.telemetry().faultTicks);
                    // the handle's position reached the audio side, in model units (gain 1: metres)
                    assertTrue(got[0]);
                    double[] dev = new double[2];
                    loop.devicePosition(dev);
                    assertEquals(dev[0], seen[0], 1e-3);
                    assertEquals(dev[1], seen[1], 1e-3);
                    assertFalse(Double.isNaN(seen[0]));
                } finally {
                    stop[0] = true;
                    audio.join(2000);
                }
            }
        }
    }
}
