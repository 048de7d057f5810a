package tactus.stability;

import static org.junit.jupiter.api.Assertions.fail;

import java.util.SplittableRandom;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Regression test for a defect the hard-case work found and the engine then fixed: on an axis that another
 * module keeps away from zero (here an unrelated Ground3D at z = 1), the guard flushes decayed masses one by
 * one, and it must also make the SpringDamper1D links between them forget their tiny previous length;
 * otherwise the damper sees a phantom velocity Z (0 - dp), re-excites the masses, and they pass through
 * subnormal positions (on a 32-mass string at 44.1 kHz, ~300 steps at ~3,200 instead of ~300 ns/step).
 */
class BusyAxisFlushTest {

    @Test
    @DisplayName("a decayed 1D chain on a busy z axis never passes through subnormal positions")
    void busyAxisOneDimensionalLinksGoSubnormal() {
        PhysicalModel pm = new PhysicalModel(1000);
        SplittableRandom rnd = new SplittableRandom(99);
        pm.addGround1D("g", new Vect3D());
        pm.addGround3D("lamp", new Vect3D(0, 0, 1));
        double s = Math.scalb(1.0, -500);
        for (int i = 0; i < 12; i++) {
            pm.addMass1D("m" + i, 1.0 + i % 3, new Vect3D(0, 0, s * (2 * rnd.nextDouble() - 1)), new Vect3D());
        }
        for (int i = 0; i <= 12; i++) {
            pm.addSpringDamper1D("k" + i, 0, 0.7, 0.001, i == 0 ? "g" : "m" + (i - 1), i == 12 ? "g" : "m" + i);
        }
        pm.init();
        for (int step = 1; step <= 10_000; step++) {
            pm.computeStep();
            for (int i = 0; i < 12; i++) {
                double z = Math.abs(pm.getMatPosition("m" + i).z);
                if (z != 0 && z < Double.MIN_NORMAL) {
                    fail("m" + i + " is subnormal at step " + step + ": z = " + z);
                }
            }
        }
    }
}
