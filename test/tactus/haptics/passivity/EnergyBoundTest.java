package tactus.haptics.passivity;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.haptics.AvatarLink;
import tactus.haptics.Board;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.HapticLoop;
import tactus.haptics.emulator.BoardEmulator;

/**
 * The energy bound ({@link EnergyBound}, {@code HapticLoop.useStiffContacts}) on one axis of the emulator's plant with
 * the hold and one tick of delay ({@link SampledPlant}), a pen-grip-like hand (0.05 kg with the handle, 300 N/m,
 * 2 N s/m; assumed) and a stiff one-sided wall whose stiffness and presence a test may change while the handle is
 * inside: the device gives the hand at most 40 uJ at any tick (the 10 uJ seed and what one exchange leaks), the force
 * never steps by more than 0.5 N. Simulated time. What this fixture shows the bound does not do yet (a slow press into
 * a 16 kN/m wall by this frictionless light handle ends with no force at all) is in docs/haptics-stability.md.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class EnergyBoundTest {
    private static final double T = 1e-3;
    private static final double BOUND = 1600;          // N/m, HapticLoop.TWO_DIY_STIFF_CONTACT
    private static final double STIFF = 16_000;        // N/m, the model's wall (400 K0 on the 2DIY)
    /**
     * The energy (J) the hand may get at any tick: the 10 uJ seed and what one exchange leaks before the cap reacts
     * (4 Hz taps: 34.5 uJ since the fixture's one tick of delay lasts a whole tick, not one 50 us substep less).
     */
    private static final double TOLERANCE = 4e-5;
    private static final double STEP = 0.5;

    /** A one-sided wall at x = 0 (free space at x > 0), stiffness and presence settable between ticks. */
    private static final class Wall implements AvatarLink {
        double stiffness;
        boolean present = true;
        private double x;

        Wall(double stiffness) {
            this.stiffness = stiffness;
        }

        @Override
        public void setTarget(double px, double py, double pz) {
            x = px;
        }

        @Override
        public void takeForce(double[] out) {
            out[0] = present && x < 0 ? -stiffness * x : 0;
            out[1] = 0;
            out[2] = 0;
        }

        @Override
        public void step(int n) {
        }
    }

    /** A run's figures: the most energy the device had given the hand at any tick (J) and the largest force step (N). */
    private static final class Run {
        final SampledPlant plant;
        final PortRig rig;
        final Wall wall;
        double peakToHand = Double.NEGATIVE_INFINITY;
        double largestStep;
        private double last;
        private int ticks;

        Run(double wallStiffness, double bound, double start) {
            plant = new SampledPlant(0.05, 0.06, T, 1).hand(300, 2);
            plant.x = start;
            plant.intend(start);
            wall = new Wall(wallStiffness);
            rig = new PortRig(plant, wall);
            rig.port.setDelay(1);
            rig.port.setEnergyBound(bound);
            rig.port.start(T);
        }

        void tick() {
            rig.tick();
            if (ticks++ > 0) {
                largestStep = Math.max(largestStep, Math.abs(rig.sent - last));
            }
            last = rig.sent;
            peakToHand = Math.max(peakToHand, plant.workOnHandle);
        }

        void ticks(int n) {
            for (int i = 0; i < n; i++) {
                tick();
            }
        }
    }

    @Test
    void aWallThatAppearsAroundTheHandleDoesNotPushItOut() {
        for (double bound : new double[] {BOUND, 0}) {
            Run r = new Run(STIFF, bound, -0.003);
            r.wall.present = false;
            r.ticks(100);
            r.wall.present = true;   // 3 mm inside a 16 kN/m wall: 48 N asked for at once
            r.ticks(1500);
            if (bound > 0) {
                assertTrue(r.peakToHand <= TOLERANCE, "energy to the hand " + r.peakToHand + " J");
                assertTrue(r.largestStep <= STEP, "force step " + r.largestStep + " N");
            } else {
                assertTrue(r.peakToHand > 1e-3, "without the bound the wall throws the hand out: " + r.peakToHand + " J");
            }
        }
    }

    @Test
    void fastTapsGetNoEnergyBack() {
        for (double hz : new double[] {2, 4}) {
            Run r = new Run(STIFF, BOUND, 0.002);   // (8 Hz taps leak 95 uJ: docs/haptics-stability.md, "Stiff contacts")
            double w = 2 * Math.PI * hz;
            for (int i = 0; i < 2000; i++) {
                r.plant.intend(0.002 - 0.004 * (1 - Math.cos(w * i * T)));   // from 2 mm out to 6 mm in and back
                r.tick();
            }
            assertTrue(r.plant.travelled() != 0 && r.peakToHand <= TOLERANCE, hz + " Hz taps: energy to the hand "
                    + r.peakToHand + " J");
            assertTrue(r.largestStep <= STEP, hz + " Hz taps: force step " + r.largestStep + " N");
        }
    }

    @Test
    void theConfigurationCallSetsTheBoundAndRejectsBadStiffnessUnchanged() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        try (Board board = new Board(emulator.connect())) {
            Device device = new Device((byte) 3, board);
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), new Wall(1));
            assertEquals(0, loop.energyBound(), 0, "off by default");
            loop.setPassivityControl(true);
            loop.setVirtualCoupling(new VirtualCoupling(300, 0.1, 0.01));
            assertEquals(HapticLoop.TWO_DIY_STIFF_CONTACT, loop.recommendedStiffContact(), 0, "a planar device");
            loop.useStiffContacts();
            assertEquals(HapticLoop.TWO_DIY_STIFF_CONTACT, loop.energyBound(), 0);
            assertEquals(HapticLoop.ROBUST_COUNT_RESERVE, loop.energyBoundCountReserve(), 0);
            loop.setEnergyBoundCountReserve(0);
            loop.useStiffContacts(HapticLoop.TWO_DIY_STIFF_CONTACT);
            assertEquals(0, loop.energyBoundCountReserve(), 0, "the explicit call leaves the reserve as it is");
            assertEquals(0.5, loop.forceRiseLimit(), 0);
            assertEquals(2, loop.energyBoundTrim(), 0);
            assertTrue(loop.isHoldCompensation());
            assertFalse(loop.isPassivityControl());
            assertNull(loop.virtualCoupling());
            for (double bad : new double[] {0.5, 0, -1, Double.NaN, Double.POSITIVE_INFINITY}) {
                String m = assertThrows(IllegalArgumentException.class, () -> loop.setEnergyBoundTrim(bad)).getMessage();
                assertTrue(m.contains("setEnergyBoundTrim") && m.contains(String.valueOf(bad)), m);
                assertEquals(2, loop.energyBoundTrim(), 0, "unchanged after " + bad);
            }
            for (double bad : new double[] {0, -3, Double.NaN, Double.POSITIVE_INFINITY}) {
                String m = assertThrows(IllegalArgumentException.class, () -> loop.useStiffContacts(bad)).getMessage();
                assertTrue(m.contains("useStiffContacts") && m.contains(String.valueOf(bad)), m);
                assertEquals(HapticLoop.TWO_DIY_STIFF_CONTACT, loop.energyBound(), 0, "unchanged after " + bad);
            }
            assertTrue(assertThrows(IllegalArgumentException.class, () -> loop.setEnergyBound(-2)).getMessage()
                    .contains("-2"));
            assertTrue(assertThrows(IllegalArgumentException.class, () -> loop.setForceRiseLimit(0)).getMessage()
                    .contains("0"));
            assertEquals(HapticLoop.TWO_DIY_STIFF_CONTACT, loop.energyBound(), 0);
            assertEquals(0.5, loop.forceRiseLimit(), 0);
            loop.setEnergyBound(0);
            assertEquals(0, loop.energyBound(), 0);
        }
    }

    @Test
    void theForceChangesByAtMostTheStepLimitPerTickWhetherItRisesFallsOrTurns() {
        EnergyBound b = new EnergyBound();
        b.setStiffness(1600);
        b.setRise(0.5);
        double[] f = {0, 0, 0};
        applyAtRest(b, f);       // switched on, with the seed only
        // then, each tick, a budget far above what these forces hold: only the step limit acts
        double[] last = {0, 0, 0};
        double[][] asked = {{3, 0, 0}, {3, 0, 0}, {3, 0, 0}, {3, 0, 0}, {3, 0, 0}, {3, 0, 0}, {3, 0, 0},
            {0, 0, 0}, {0, 0, 0}, {-3, 0, 0}, {0, 3, 0}, {0.2, 0.1, 0}};
        double[][] expected = {{0.5, 0, 0}, {1, 0, 0}, {1.5, 0, 0}, {2, 0, 0}, {2.5, 0, 0}, {3, 0, 0}, {3, 0, 0},
            {2.5, 0, 0}, {2, 0, 0}, {1.5, 0, 0}, null, null};
        for (int t = 0; t < asked.length; t++) {
            System.arraycopy(asked[t], 0, f, 0, 3);
            b.observe(1.0);
            applyAtRest(b, f);
            double step = Math.sqrt((f[0] - last[0]) * (f[0] - last[0]) + (f[1] - last[1]) * (f[1] - last[1])
                    + (f[2] - last[2]) * (f[2] - last[2]));
            assertTrue(step <= 0.5 + 1e-12, "tick " + t + ": step " + step + " N");
            if (expected[t] != null) {
                for (int i = 0; i < 3; i++) {
                    assertEquals(expected[t][i], f[i], 1e-12, "tick " + t + ", axis " + i);
                }
            }
            System.arraycopy(f, 0, last, 0, 3);
        }
        b.setStiffness(0);   // off: the force goes out as asked, whatever the last one was
        f[0] = -4;
        f[1] = 0;
        applyAtRest(b, f);
        assertEquals(-4, f[0], 0);
    }

    /** A bound at {@link #BOUND} with this seed (J) and step limit (N per tick). */
    private static EnergyBound bound(double seed, double rise) {
        EnergyBound b = new EnergyBound();
        b.setStiffness(BOUND);
        b.setSeed(seed);
        b.setRise(rise);
        return b;
    }

    /** Sends the bound one tick: energy in (J), then the model's force along x (N); returns the force sent, N. */
    private static double tick(EnergyBound b, double intoModel, double want) {
        b.observe(intoModel);
        double[] f = {want, 0, 0};
        applyAtRest(b, f);
        return f[0];
    }

    /**
     * The force sent, N, by a bound at 3300 N/m (step limit out of the way) that has taken 1 mJ in and is asked for 20 N
     * along +x (so the cap binds), with the handle moving at v (m/s along x), a tick of 1 ms held for {@code hold} s and
     * the sensor's count q (m) on every axis.
     */
    private static double capped(boolean compensation, double v, double hold, double q) {
        EnergyBound b = new EnergyBound();
        b.setStiffness(3300);
        b.setRise(100);
        b.setQuantum(q, q, q);
        b.setHoldCompensation(compensation);
        double[] f = {20, 0, 0};
        b.apply(f, new double[] {0, 0, 0}, T, hold);   // switched on
        b.observe(1e-3);
        f[0] = 20;
        b.apply(f, new double[] {v, 0, 0}, T, hold);
        return f[0];
    }

    @Test
    void theHoldCompensationMovesTheCapByTheDampingTheHoldTakesWhereTheSensorIsFine() {
        double still = capped(false, 0, 0.5 * T, 0);
        assertEquals(Math.sqrt(2 * 3300 * (1e-3 + EnergyBound.DEFAULT_SEED)), still, 1e-9, "the spring's cap");
        for (double hold : new double[] {0.5 * T, 1.5 * T}) {
            for (double v : new double[] {-0.02, -0.001, 0.001, 0.02}) {
                String at = "hold " + hold + " s, v " + v + " m/s: ";
                // outwards (v > 0, along the force) the cap falls, inwards it rises, by K hold v
                assertEquals(still - 3300 * hold * v, capped(true, v, hold, 0), 1e-9, at + "compensated");
                assertEquals(still, capped(false, v, hold, 0), 1e-12, at + "off");
                // a 2DIY count (148 um): one count per tick would move the cap by 0.24 N or more, so no compensation
                assertEquals(still, capped(true, v, hold, 1.48e-4), 1e-12, at + "coarse sensor");
                // a 1 um count moves it by at most 1.65 mN at half a tick: compensated
                assertEquals(still - 3300 * hold * v, capped(true, v, hold, 1e-6), 1e-9, at + "fine sensor");
            }
        }
        assertEquals(0, capped(true, 1000, 0.5 * T, 0), 0, "the cap never pulls");
    }

    @Test
    void theTrimKeepsTheBudgetWithinItsRatioOfWhatTheForceSentHolds() {
        for (double r : new double[] {1, 2, 8}) {
            EnergyBound b = bound(1e-5, 100);
            b.setTrim(r);
            tick(b, 0, 0);
            for (double force : new double[] {0.3, 1.0, 0.1}) {
                double sent = tick(b, 1e-2, force);   // far more energy in than the force holds
                assertEquals(force, sent, 1e-12, "r " + r + ": the cap does not bind");
                assertEquals(r * force * force / (2 * BOUND), b.budget(), 1e-15, "r " + r + ", " + force + " N");
            }
        }
    }

    @Test
    void theCountReserveCapsTheForceSoThatOneCountBackNeverTakesMoreThanItsShareOfTheBudget() {
        double q = 1.48e-4;   // a 2DIY count at the handle, m
        for (double c : new double[] {1.25, 1.75, 3}) {
            for (double rise : new double[] {0.5, 100}) {
                EnergyBound b = bound(1e-5, rise);
                b.setQuantum(q, q, 0);
                b.setCountReserve(c);
                double sent = tick(b, 0, 20);
                String at = "c = " + c + ", rise " + rise + ": ";
                assertEquals(1e-5 / (c * q), sent, 1e-9, at + "the onset is the seed over c counts");
                // press in count by count at the force sent, then flicker back one count: the budget the cap then
                // allows never falls below (1 - 1/c) of what it was, and never to zero
                double before = b.budget() + b.seed();
                for (int n = 0; n < 40; n++) {
                    double available = b.budget() + b.seed();
                    double back = tick(b, -sent * q, 20);
                    double left = b.budget() + b.seed();
                    assertTrue(left >= (1 - 1 / c) * available - 1e-12, at + "count " + n + ": " + left + " J of "
                            + available);
                    assertTrue(back > 0, at + "count " + n + ": the wall is lost");
                    sent = tick(b, back * q, 20);      // the count back in, credited at the force that acted
                    sent = tick(b, sent * q, 20);      // and one count further in
                }
                // a count back and in again keeps (1 - 1/c^2) of the budget, the next count in adds 1/c: pressing in
                // with a flicker at every count grows the budget when (1 - 1/c^2)(1 + 1/c) > 1 (c = 1.75: 1.057)
                boolean grows = (1 - 1 / (c * c)) * (1 + 1 / c) > 1;
                assertEquals(grows, b.budget() + b.seed() > before, at + "pressing in grows the budget: "
                        + (b.budget() + b.seed()) + " J from " + before);
                // above the reserve the cap is the spring's: F^2 / 2K + B* / 2 = B
                double reserved = c * c * q * q * BOUND;
                EnergyBound big = bound(1e-3, 100);
                big.setQuantum(q, q, 0);
                big.setCountReserve(c);
                double f = tick(big, 0, 50);
                assertEquals(Math.sqrt(2 * BOUND * (1e-3 - reserved / 2)), f, 1e-9, at + "the spring's cap");
            }
        }
    }

    @Test
    void withoutACountReserveOrWithoutAQuantumTheCapIsTheSpringsAsBefore() {
        for (double[] qc : new double[][] {{1.48e-4, 0}, {0, 1.75}}) {
            EnergyBound b = bound(1e-5, 100);
            b.setQuantum(qc[0], qc[0], qc[0]);
            b.setCountReserve(qc[1]);
            assertEquals(Math.sqrt(2 * BOUND * 1e-5), tick(b, 0, 20), 1e-12, "q " + qc[0] + ", c " + qc[1]);
        }
    }

    @Test
    void theLoopValidatesTheCountReserve() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        try (Board board = new Board(emulator.connect())) {
            HapticLoop loop = new HapticLoop(new Device((byte) 3, board), HaplyPreset.HAPLY_2018.newKinematics(),
                    new Wall(1));
            for (double bad : new double[] {-1, Double.NaN, Double.POSITIVE_INFINITY}) {
                IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                        () -> loop.setEnergyBoundCountReserve(bad));
                assertTrue(e.getMessage().contains("setEnergyBoundCountReserve") && e.getMessage().contains(
                        String.valueOf(bad)), e.getMessage());
                assertEquals(0, loop.energyBoundCountReserve(), "unchanged after " + bad);
            }
            loop.setEnergyBoundCountReserve(HapticLoop.ROBUST_COUNT_RESERVE);
            assertEquals(HapticLoop.ROBUST_COUNT_RESERVE, loop.energyBoundCountReserve());
        }
    }

    @Test
    void aCreditPaysForForceAfterTheSeedIsGivenBackButNotWhileNoForceIsWanted() {
        EnergyBound b = bound(1e-5, 100);
        assertEquals(Math.sqrt(2 * BOUND * 1e-5), tick(b, 0, 20), 1e-12, "the seed's force");
        // the contact gives the hand back more than the seed: the budget sits at the port's net, -12 uJ
        assertEquals(0, tick(b, -1.2e-5, 20), 0, "no force once the seed is given back");
        assertEquals(-1.2e-5, b.budget(), 1e-15);
        assertEquals(0, tick(b, 0, 20), 0, "and none later: nothing came in");
        // energy the device's own damping took from the hand pays for force again: 0.5 N s/m over 10 mm in 50 ms
        // dissipates at least 0.5 * 0.01^2 / 0.05 = 1 mJ; friction of 0.01 N over it, 0.1 mJ more; a count of
        // 0.1 mm on each axis is taken off what the handle certainly moved
        b.setDissipation(0.5, 0.01);
        b.setQuantum(1e-4, 1e-4, 1e-4);
        b.credit(new double[] {0, 0.0101, 0}, new double[] {0, 0, 0}, 0.05);
        double f = tick(b, 0, 20);
        assertEquals(Math.sqrt(2 * BOUND * (1e-3 + 1e-4 - 1.2e-5 + 1e-5)), f, 1e-9, "the credit pays for force");
        b.credit(new double[] {1e-4, 0, 0}, new double[] {0, 0, 0}, 0.001);
        assertEquals(f, tick(b, 0, 20), 1e-12, "one count of motion is credited nothing");
        // a credit earned while no force is wanted is trimmed away: no reserve for a later contact
        EnergyBound idle = bound(1e-5, 100);
        tick(idle, 0, 0);
        idle.setDissipation(0.5, 0);
        idle.credit(new double[] {0, 0.01, 0}, new double[] {0, 0, 0}, 0.05);
        tick(idle, 0, 0);
        assertEquals(0, idle.budget(), 0, "trimmed with no force");
        assertEquals(Math.sqrt(2 * BOUND * 1e-5), tick(idle, 0, 20), 1e-12, "the next contact starts with the seed");
    }

    @Test
    void theLoopValidatesTheDeviceDissipation() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        try (Board board = new Board(emulator.connect())) {
            HapticLoop loop = new HapticLoop(new Device((byte) 3, board), HaplyPreset.HAPLY_2018.newKinematics(),
                    new Wall(1));
            double[][] bad = {{-1, 0}, {0, -0.1}, {Double.NaN, 0}, {0, Double.POSITIVE_INFINITY}};
            for (double[] v : bad) {
                IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                        () -> loop.setDeviceDissipation(v[0], v[1]));
                assertTrue(e.getMessage().contains("setDeviceDissipation") && e.getMessage().contains(
                        String.valueOf(v[0])) && e.getMessage().contains(String.valueOf(v[1])), e.getMessage());
                assertEquals(0, loop.deviceDamping(), 0, "unchanged");
                assertEquals(0, loop.deviceFriction(), 0, "unchanged");
            }
            loop.setDeviceDissipation(0.25, 0.02);
            assertEquals(0.25, loop.deviceDamping(), 0);
            assertEquals(0.02, loop.deviceFriction(), 0);
        }
    }

    /** Bounds f as the loop would for a handle at rest (no velocity: the hold compensation moves nothing), 1 kHz. */
    private static void applyAtRest(EnergyBound b, double[] f) {
        b.apply(f, new double[3], 1e-3, 0);
    }
}
