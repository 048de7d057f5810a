package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class ExchangeAvatarLinkTest {

    @Test
    void handsTheLoopTheSumAndItsStepCountInEitherForceMode() {
        for (AvatarExchange.ForceMode mode : AvatarExchange.ForceMode.values()) {
            AvatarExchange ex = new AvatarExchange(mode);
            ExchangeAvatarLink link = new ExchangeAvatarLink(ex);
            double sx = 0;
            double sy = 0;
            int steps = 37;
            for (int i = 0; i < steps; i++) {
                double fx = 0.25 * i - 3;
                double fy = Math.sin(i);
                ex.addForce(fx, fy, 0);
                sx += fx;
                sy += fy;
            }
            double[] out = new double[3];
            assertEquals(steps, link.takeForceCounted(out), mode + ": steps");
            assertEquals(sx, out[0], 1e-12 * steps, mode + ": sum x");
            assertEquals(sy, out[1], 1e-12 * steps, mode + ": sum y");
            assertEquals(0, link.takeForceCounted(out), mode + ": nothing new");
            assertArrayEquals(new double[3], out, mode + ": no force without steps");
            ex.addForce(2, 0, 0);
            ex.addForce(4, 0, 0);
            link.takeForce(out);
            assertEquals(6, out[0], 1e-12, mode + ": takeForce gives the sum, as AvatarLink says");
        }
    }

    @Test
    void positionsReachTheAudioSideAndNothingWaits() {
        AvatarExchange ex = new AvatarExchange();
        ExchangeAvatarLink link = new ExchangeAvatarLink(ex);
        link.setTarget(1.5, -2, 0.25);
        double[] p = new double[3];
        assertTrue(ex.readPosition(p));
        assertArrayEquals(new double[] {1.5, -2, 0.25}, p);
        assertTrue(link.neverWaits());
        assertThrows(IllegalArgumentException.class, () -> new ExchangeAvatarLink(null));
    }
}
