package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import org.junit.jupiter.api.Test;

/**
 * {@code setMoveKeepsLinkHistory}: what a hand move ({@code setMatPosition}, {@code setMatPosAt},
 * {@code Mass.setPosition}) does to the moved mass's links. The expected trajectories come from the scheme's
 * equations, stepped here by hand: each mass X(n+1) = 2X(n) - X(n-1) + F/M; each link stores the distance d it saw
 * at its last step, and at the next one sets d_prev = d, d = |X1 - X2| and applies
 * f = -K (d - l0) - Z (d - d_prev) along the unit vector from mass 2 to mass 1. A move sets X = X(n-1) = p and keeps
 * the pending forces; the paper's engine leaves d alone (the damper sees the jump), Tactus by default sets
 * d = the distance after the move.
 */
class MoveKeepsLinkHistoryTest {
    static final double K = 0.1;
    static final double Z = 0.05;
    static final double L0 = 1;
    static final double M = 1.5;

    /** A fixed point g, and masses a and b in a chain g - a - b of spring-dampers, off the x axis. */
    static PhysicalModel chain() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        m.addMass3D("a", M, new Vect3D(1.3, 0.2, 0), new Vect3D(0, 0, 0));
        m.addMass3D("b", M, new Vect3D(2.1, 0.1, 0.3), new Vect3D(0, 0, 0));
        m.addSpringDamper3D("ga", L0, K, Z, "g", "a");
        m.addSpringDamper3D("ab", L0, K, Z, "a", "b");
        m.init();
        return m;
    }

    /** The same chain, stepped by hand from the scheme's equations. */
    static final class HandChain {
        final double[][] x = {{0, 0, 0}, {1.3, 0.2, 0}, {2.1, 0.1, 0.3}};
        final double[][] xr = {{0, 0, 0}, {1.3, 0.2, 0}, {2.1, 0.1, 0.3}};
        final double[][] f = new double[3][3];
        final int[][] links = {{0, 1}, {1, 2}};
        final double[] d = new double[2];

        HandChain() {
            for (int l = 0; l < 2; l++) {
                d[l] = dist(links[l][0], links[l][1]);
            }
        }

        double dist(int i, int j) {
            double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
            return Math.sqrt(dx * dx + dy * dy + dz * dz);
        }

        void step() {
            for (int i = 1; i < 3; i++) {   // mass 0 is the fixed point
                for (int k = 0; k < 3; k++) {
                    double next = 2 * x[i][k] - xr[i][k] + f[i][k] / M;
                    xr[i][k] = x[i][k];
                    x[i][k] = next;
                    f[i][k] = 0;
                }
            }
            for (int k = 0; k < 3; k++) {
                f[0][k] = 0;
            }
            for (int l = 0; l < 2; l++) {
                int i = links[l][0], j = links[l][1];
                double prev = d[l];
                d[l] = dist(i, j);
                double force = -K * (d[l] - L0) - Z * (d[l] - prev);
                for (int k = 0; k < 3; k++) {
                    double u = (x[i][k] - x[j][k]) / d[l];
                    f[i][k] += force * u;
                    f[j][k] -= force * u;
                }
            }
        }

        void move(int i, double[] p, boolean keepHistory) {
            x[i] = p.clone();
            xr[i] = p.clone();
            if (!keepHistory) {
                for (int l = 0; l < 2; l++) {
                    if (links[l][0] == i || links[l][1] == i) {
                        d[l] = dist(links[l][0], links[l][1]);
                    }
                }
            }
        }
    }

    /** Runs both, moving mass a after 7 steps (by name, index or handle), and returns the largest difference. */
    static double largestDifference(boolean modelKeeps, boolean handKeeps, int how) {
        PhysicalModel m = chain();
        m.setMoveKeepsLinkHistory(modelKeeps);
        HandChain h = new HandChain();
        double[] p = {1.7, -0.4, 0.25};
        double worst = 0;
        for (int n = 0; n < 20; n++) {
            if (n == 7) {
                Vect3D to = new Vect3D(p[0], p[1], p[2]);
                if (how == 0) {
                    m.setMatPosition("a", to);
                } else if (how == 1) {
                    m.setMatPosAt(m.getMatIndex("a"), to);
                } else {
                    ((Mass) m.getMass("a")).setPosition(to);
                }
                h.move(1, p, handKeeps);
            }
            m.computeStep();
            h.step();
            String[] names = {"a", "b"};
            for (int i = 0; i < 2; i++) {
                Vect3D got = m.getMatPosition(names[i]);
                double[] want = h.x[i + 1];
                worst = Math.max(worst, Math.max(Math.abs(got.x - want[0]),
                        Math.max(Math.abs(got.y - want[1]), Math.abs(got.z - want[2]))));
            }
        }
        return worst;
    }

    @Test
    void withTheOptionTheMovedMassesDampersSeeTheJumpAsThePapersEngineDid() {
        for (int how = 0; how < 3; how++) {
            assertTrue(largestDifference(true, true, how) < 1e-12, "the paper engine's scheme, move " + how);
            assertTrue(largestDifference(true, false, how) > 1e-4, "and not Tactus's, move " + how
                    + ": the test tells them apart");
        }
    }

    @Test
    void byDefaultTheMovedMassesLinksForgetTheirHistory() {
        assertFalse(new PhysicalModel(1000, 50).getMoveKeepsLinkHistory());
        for (int how = 0; how < 3; how++) {
            assertTrue(largestDifference(false, false, how) < 1e-12, "Tactus's scheme, move " + how);
            assertTrue(largestDifference(false, true, how) > 1e-4, "and not the paper engine's, move " + how);
        }
    }

    /**
     * In realtime mode the move made on another thread is queued and applied by the stepping thread between two
     * steps, keeping the history all the same.
     */
    @Test
    void aMoveQueuedForTheRealtimeOwnerKeepsTheHistoryToo() {
        assertTimeoutPreemptively(Duration.ofSeconds(30), () -> {
            PhysicalModel m = chain();
            m.setMoveKeepsLinkHistory(true);
            m.beginRealtimeStepping();
            CountDownLatch firstSteps = new CountDownLatch(1);
            CountDownLatch moved = new CountDownLatch(1);
            Thread audio = new Thread(() -> {
                m.computeNSteps(7);
                firstSteps.countDown();
                try {
                    moved.await();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                m.computeNSteps(13);
            }, "audio");
            audio.start();
            firstSteps.await();
            long posted = m.gate.mode().postedSeq();
            m.setMatPosition("a", new Vect3D(1.7, -0.4, 0.25));
            assertEquals(posted + 1, m.gate.mode().postedSeq(), "the move was queued for the owner");
            moved.countDown();
            audio.join();
            m.endRealtimeStepping();

            HandChain h = new HandChain();
            for (int n = 0; n < 20; n++) {
                if (n == 7) {
                    h.move(1, new double[] {1.7, -0.4, 0.25}, true);
                }
                h.step();
            }
            Vect3D b = m.getMatPosition("b");
            assertEquals(h.x[2][0], b.x, 1e-12);
            assertEquals(h.x[2][1], b.y, 1e-12);
            assertEquals(h.x[2][2], b.z, 1e-12);
        });
    }

    @Test
    void theOptionReadsBack() {
        PhysicalModel m = chain();
        m.setMoveKeepsLinkHistory(true);
        assertTrue(m.getMoveKeepsLinkHistory());
        m.setMoveKeepsLinkHistory(false);
        assertEquals(false, m.getMoveKeepsLinkHistory());
    }
}
