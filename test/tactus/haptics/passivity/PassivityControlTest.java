package tactus.haptics.passivity;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.haptics.AvatarLink;
import tactus.haptics.NoForceAvatar;

/**
 * The passivity observer, the time-domain passivity controller and the virtual coupling, on one axis of the emulator's
 * {@link tactus.haptics.emulator.DevicePlant} driven through a zero-order hold, in simulated time (deterministic). Plant: 0.05 kg handle with 0.5 N s/m, at 1 kHz; the
 * hand adds 0.1 kg, a 300 N/m grip and 1 N s/m. Without control the sampled wall is stable only below about
 * 2 b / T (b the total damping): 3000 N/m with the hand, 1000 N/m for the handle alone (Colgate &amp; Schenkel).
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class PassivityControlTest {
    private static final double T = 1e-3;

    /** A spring to the origin, F = -K x, computed here: the port with no model behind it. */
    private static double[] scriptedExchange(double k, double step, int n, int delay) {
        HapticPort port = new HapticPort();
        port.setDelay(delay);
        port.start(T);
        double[] target = new double[3];
        double[] f = new double[3];
        for (int i = 0; i <= 2 * n; i++) {
            double x = (i <= n ? i : 2 * n - i) * step;
            port.sense(x, 0, 0, target);
            f[0] = -k * x;
            f[1] = 0;
            f[2] = 0;
            port.command(f);
            port.sent(1);
        }
        PassivityObserver o = port.observer();
        return new double[] {o.energyIn(), o.energyOut(), o.netEnergy(), o.ticks()};
    }

    @Test
    void observerMatchesTheAnalyticEnergyOfAHeldSpringPushedInAndOut() {
        // in by n steps of h and back: the held force -K x(k) acts over [x(k), x(k+1)], so the way in stores
        // K h^2 n (n - 1) / 2 and the way out returns K h^2 n (n + 1) / 2: the hold creates K X h, X = n h
        double k = 2000;
        double h = 1e-5;
        int n = 100;
        double[] e = scriptedExchange(k, h, n, 0);
        assertEquals(k * h * h * n * (n - 1) / 2, e[0], 1e-15, "energy in");
        assertEquals(k * h * h * n * (n + 1) / 2, e[1], 1e-15, "energy out");
        assertEquals(-k * n * h * h, e[2], 1e-15, "net: the energy the hold created");
        assertEquals(2 * n, (long) e[3], "one record per tick after the first");
        // with one tick of delay each displacement is charged to the force sent one tick before it
        double[] d = scriptedExchange(k, h, n, 1);
        assertEquals(k * h * h * (double) (n - 1) * (n - 2) / 2, d[0], 1e-15, "energy in, one tick late");
        // and the way out is charged one step deeper: the hold and the delay create 3 K h^2 (n - 1)
        assertEquals(-3 * k * h * h * (n - 1), d[2], 1e-15, "net with one tick of delay");
    }

    @Test
    void observerMatchesTheWorkDoneOnTheSimulatedHandle() {
        for (int delay = 0; delay <= 1; delay++) {
            SampledPlant p = new SampledPlant(0.15, 0.5, T, delay).hand(300, 1);
            p.x = 0.002;
            PortRig rig = new PortRig(p, PortRig.wall(3000, 0, p.x)).start(delay);
            p.intend(-0.002);
            for (int i = 0; i < 500; i++) {
                rig.tick();
            }
            double work = p.workOnHandle;
            assertTrue(Math.abs(work) > 1e-5, "the exchange is not trivial: " + work);
            // the observer lags the plant by the last interval, and the plant's delayed torque may start a substep
            // (1/200 of a tick) late: within 1 %
            assertEquals(-work, rig.port.observer().netEnergy(), 1e-2 * Math.abs(work) + lastStep(rig), "delay " + delay);
        }
    }

    /** The work of the last tick's force over the last interval, which the observer sees only at the next tick. */
    private static double lastStep(PortRig rig) {
        return Math.abs(rig.sent) * 1e-4;
    }

    /** Figures of one run: {work on the handle (J), peak |v| over the last second (m/s), final x (m)}. */
    private static double[] holdAgainstWall(double k, int delay, String variant) {
        SampledPlant p = new SampledPlant(0.15, 0.5, T, delay).hand(300, 1);
        p.x = 0.002;
        PortRig rig = new PortRig(p, PortRig.wall(k, 0, p.x));
        if (variant.contains("coupling")) {
            rig.port.setCoupling(VirtualCoupling.forDevice(1.5, T, delay));
        }
        rig.port.setControl(variant.contains("pc"));
        rig.start(delay);
        p.intend(-0.002);   // the hand pushes 2 mm into the wall and holds
        double late = 0;
        for (int i = 0; i < 3000 && Math.abs(p.x) < 1; i++) {
            rig.tick();
            if (i >= 2000) {
                late = Math.max(late, Math.abs(p.v));
            }
        }
        if (Math.abs(p.x) >= 1) {
            late = Double.POSITIVE_INFINITY;   // ran away
        }
        return new double[] {p.workOnHandle, late, p.x};
    }

    @Test
    void passivityControllerSettlesAWallTenTimesAboveTheBoundAndReturnsNoEnergy() {
        double k = 30_000;   // 10 x 2 b / T with the hand's damping
        double[] off = holdAgainstWall(k, 0, "none");
        assertTrue(off[0] > 1e-3, "without control the wall gives the hand energy: " + off[0] + " J");
        assertTrue(off[1] > 0.01, "without control the contact keeps oscillating: late peak " + off[1] + " m/s");
        double[] on = holdAgainstWall(k, 0, "pc");
        assertTrue(on[0] <= 1e-6, "with the controller the hand gets no energy back: " + on[0] + " J (uncontrolled "
                + off[0] + " J)");
        assertTrue(on[1] < 1e-3, "with the controller the contact settles: late peak " + on[1] + " m/s");
        // with one tick of exchange delay the bound is 2 b / (3 T) = 1000 N/m: 20 x that
        double[] offLate = holdAgainstWall(20_000, 1, "none");
        double[] onLate = holdAgainstWall(20_000, 1, "pc");
        assertTrue(offLate[1] > 0.01, "delayed, uncontrolled: oscillates (late peak " + offLate[1] + " m/s)");
        assertTrue(onLate[1] < 1e-3, "delayed, controlled: settles (late peak " + onLate[1] + " m/s)");
        assertTrue(onLate[0] < 1e-3 * offLate[0], "delayed, controlled: energy returned " + onLate[0] + " J against "
                + offLate[0] + " J uncontrolled");
    }

    @Test
    void theHandleAloneGetsNoEnergyFromTheWallWithTheController() {
        for (double k : new double[] {10_000, 40_000}) {   // 10 and 40 x the handle's bound 2 b / T
            double[] v = new double[2];
            for (int c = 0; c < 2; c++) {
                SampledPlant p = new SampledPlant(0.05, 0.5, T, 0);
                p.x = 0.002;
                p.v = -0.05;
                PortRig rig = new PortRig(p, PortRig.wall(k, 0, p.x));
                rig.port.setControl(c == 1);
                rig.start(0);
                for (int i = 0; i < 100; i++) {
                    rig.tick();
                }
                v[c] = p.v;
                if (c == 0) {
                    assertTrue(p.workOnHandle > 0, "uncontrolled, the wall creates energy: " + p.workOnHandle);
                } else {
                    assertTrue(p.workOnHandle <= 1e-9, "controlled, it returns none: " + p.workOnHandle);
                }
            }
            assertTrue(v[0] > 0, "K " + k + ": uncontrolled the handle bounces off: " + v[0]);
            assertTrue(v[1] >= 0 && v[1] < v[0], "K " + k + ": controlled it leaves slower: " + v[1] + " m/s against " + v[0]);
        }
    }

    @Test
    void virtualCouplingKeepsAWallStableWhereDirectRenderingIsNot() {
        double k = 20_000;   // 20 x the bound with one tick of delay
        double[] direct = holdAgainstWall(k, 1, "none");
        assertTrue(direct[1] > 0.01, "direct: unstable, late peak " + direct[1] + " m/s");
        double[] coupled = holdAgainstWall(k, 1, "coupling");
        assertTrue(coupled[1] < 1e-4, "coupled: settles, late peak " + coupled[1] + " m/s");
        assertTrue(coupled[0] <= 0, "coupled: passive, energy returned " + coupled[0] + " J");
        // what the hand feels: the coupling in series with the wall, far softer than K. At rest the grip's force
        // 300 N/m x (x - intended) is balanced by the coupling: the felt stiffness is that force over the penetration
        VirtualCoupling c = VirtualCoupling.forDevice(1.5, T, 1);
        double felt = 300 * (coupled[2] + 0.002) / -coupled[2];
        double series = k * c.stiffness() / (k + c.stiffness());
        assertEquals(series, felt, 0.05 * series, "felt stiffness " + felt + " N/m");
    }

    /** A model that is a damper (on the avatar's speed) until {@code wall} is set, then a stiff one-sided wall at 0. */
    private static final class DamperThenWall implements AvatarLink {
        private final double damping;
        private final double stiffness;
        boolean wall;
        private double x;
        private double last = Double.NaN;
        private double f;

        DamperThenWall(double damping, double stiffness) {
            this.damping = damping;
            this.stiffness = stiffness;
        }

        @Override
        public void setTarget(double px, double py, double pz) {
            x = px;
        }

        @Override
        public void step(int n) {
            if (wall) {
                f = x < 0 ? -stiffness * x : 0;
            } else {
                f = Double.isNaN(last) ? 0 : -damping * (x - last) / T;
            }
            last = x;
        }

        @Override
        public void takeForce(double[] out) {
            out[0] = f;
            out[1] = 0;
            out[2] = 0;
        }
    }

    /**
     * Energy (J) the device gave the hand while it held the handle in a stiff wall, after a long soft phase in which
     * it stirred a damper (which puts energy into the model's account): {reserve built, work on the handle in the
     * wall phase}.
     */
    private static double[] stiffContactAfterSoftStirring(double reserveLimit) {
        return stiffContactAfterSoftStirring(reserveLimit, 0);
    }

    private static double[] stiffContactAfterSoftStirring(double reserveLimit, double tolerance) {
        SampledPlant p = new SampledPlant(0.15, 0.5, T, 1).hand(300, 1);
        p.x = 0.002;
        DamperThenWall model = new DamperThenWall(2, 20_000);   // 20 x 2 b / (3 T): direct rendering buzzes
        PortRig rig = new PortRig(p, model);
        rig.port.setControl(true);
        rig.port.setReserveLimit(reserveLimit);
        rig.port.setTolerance(tolerance);
        rig.start(1);
        for (int i = 0; i < 3000; i++) {   // 3 s of stirring at 2 Hz, 4 mm: about 7 mJ into the damper
            p.intend(0.002 + 0.004 * Math.sin(2 * Math.PI * 2 * i * T));
            rig.tick();
        }
        double reserve = rig.port.observer().netEnergy();
        model.wall = true;
        double before = p.workOnHandle;
        p.intend(-0.002);   // then presses 2 mm into the wall and holds
        for (int i = 0; i < 3000 && Math.abs(p.x) < 1; i++) {
            rig.tick();
        }
        return new double[] {reserve, p.workOnHandle - before};
    }

    @Test
    void aCappedReserveKeepsAStiffContactFromGivingBackEnergyStoredLongBefore() {
        double[] uncapped = stiffContactAfterSoftStirring(Double.POSITIVE_INFINITY);
        double[] capped = stiffContactAfterSoftStirring(1e-4);
        double[] none = stiffContactAfterSoftStirring(0);
        assertTrue(uncapped[0] > 2e-3, "the stirring put energy into the account: " + uncapped[0] + " J");
        // uncapped, the controller lets the buzzing wall return the stored energy before it acts
        assertTrue(uncapped[1] > 1e-3, "uncapped: the wall gives the hand energy back: " + uncapped[1] + " J");
        assertTrue(uncapped[1] <= uncapped[0] + 1e-4, "uncapped: at most the reserve: " + uncapped[1] + " J of "
                + uncapped[0]);
        // capped, at most the cap (and what the prediction misses by a tick)
        assertTrue(capped[1] <= 2e-4, "capped at 0.1 mJ: energy to the hand " + capped[1] + " J (uncapped "
                + uncapped[1] + " J)");
        assertTrue(none[1] <= 1e-4, "no reserve at all: energy to the hand " + none[1] + " J");
    }

    @Test
    void aToleranceLetsTheWallGiveBackAtMostThatMuch() {
        // no reserve, so only the tolerance can let the buzzing wall give energy back: at most that much (and what
        // the prediction misses by a tick), and more than with no tolerance
        double[] strict = stiffContactAfterSoftStirring(0, 0);
        for (double tolerance : new double[] {5e-4, 2e-3}) {
            double[] tolerant = stiffContactAfterSoftStirring(0, tolerance);
            assertTrue(tolerant[1] <= tolerance + 1e-4, "tolerance " + tolerance + " J: energy to the hand "
                    + tolerant[1] + " J");
            assertTrue(tolerant[1] > strict[1], "tolerance " + tolerance + " J: " + tolerant[1]
                    + " J, more than with none: " + strict[1] + " J");
        }
    }

    @Test
    void aCouplingSwitchedInStartsAtTheHandleWithoutAForceStep() {
        // the hand drags the handle at 5 cm/s through free space (the model pushes nothing) while a coupling is
        // switched in, out, and in again elsewhere: the proxy starts at the handle, moving with it, every time, so
        // the force sent never jumps (a proxy left where it was would pull with k times the distance travelled)
        SampledPlant p = new SampledPlant(0.05, 0.5, T, 1).hand(300, 1);
        PortRig rig = new PortRig(p, PortRig.wall(20_000, 0, 0)).start(1);   // wall at x = 0, the hand stays above it
        VirtualCoupling c = new VirtualCoupling(400, 0.015, 0.02);
        p.x = 0.01;
        double worst = 0;
        double[] target = new double[3];
        for (int i = 0; i < 1500; i++) {
            if (i == 300 || i == 1100) {
                rig.port.setCoupling(c);
            } else if (i == 700) {
                rig.port.setCoupling(null);
            }
            p.intend(0.01 + 0.05 * i * T);
            rig.port.sense(p.x, 0, 0, target);
            if (i == 300 || i == 1100) {
                assertEquals(p.x, target[0], 0, "tick " + i + ": the proxy starts at the handle");
            }
            rig.avatar.setTarget(target[0], 0, 0);
            rig.avatar.step(1);
            double[] f = new double[3];
            rig.avatar.takeForceCounted(f);
            rig.port.command(f);
            rig.port.sent(1);
            p.send(f[0]);
            p.advance();
            worst = Math.max(worst, Math.abs(f[0]));
        }
        assertTrue(p.x > 0.06, "the hand dragged the handle: " + p.x + " m");
        // the proxy's 20 g dragged at 5 cm/s by the spring: a few mN at the switch's transient at most
        assertTrue(worst < 0.02, "largest force sent " + worst + " N (a stale proxy would pull with 400 N/m x 2 cm = 8 N)");
    }

    @Test
    void aSoftDampedWallFeelsTheSameWithTheController() {
        // a soft wall (a tenth of the bound, 100 N/m) with the damping of a typical contact (0.5 N s/m: more than the
        // 0.15 N s/m of negative damping that the hold and the delay give it), pushed in and out by the hand at 2 Hz
        double[][] traj = new double[2][];
        long[] active = new long[2];
        for (int c = 0; c < 2; c++) {
            SampledPlant p = new SampledPlant(0.15, 0.5, T, 1).hand(300, 1);
            p.x = 0.002;
            PortRig rig = new PortRig(p, PortRig.wall(100, 0.5, p.x));
            rig.port.setControl(c == 1);
            rig.start(1);
            traj[c] = new double[4000];
            for (int i = 0; i < 4000; i++) {
                p.intend(-0.004 * Math.sin(2 * Math.PI * 2 * i * T));
                rig.tick();
                traj[c][i] = p.x;
            }
            active[c] = rig.port.observer().activeTicks();
        }
        assertEquals(0, active[0], "off: never active");
        assertTrue(active[1] <= 40, "on: active in at most 1 % of 4000 ticks, was " + active[1]);
        double worst = 0;
        for (int i = 0; i < 4000; i++) {
            worst = Math.max(worst, Math.abs(traj[0][i] - traj[1][i]));
        }
        assertTrue(worst < 1e-6, "the trajectory is unchanged (within 1 um): worst " + worst + " m");
    }

    @Test
    void frictionCompensationTakesTheThresholdOffTheHandAndAddsNothingAtRest() {
        double coulomb = 0.3;
        double[] lag = new double[2];
        for (int c = 0; c < 2; c++) {
            SampledPlant p = new SampledPlant(0.15, 0.5, T, 1).coulomb(coulomb).hand(300, 1);
            PortRig rig = new PortRig(p, new NoForceAvatar());
            if (c == 1) {
                rig.port.setFriction(new FrictionCompensation(0.8 * coulomb));
            }
            rig.start(1);
            double sum = 0;
            for (int i = 0; i < 2000; i++) {
                double want = 0.05 * i * T;   // the hand drags at 5 cm/s (at 2 cm/s, compensated, it sticks and slips)
                p.intend(want);
                rig.tick();
                if (i >= 1000) {
                    sum += want - p.x;
                }
            }
            lag[c] = sum / 1000;
        }
        // the grip stretches until it overcomes friction and damping (the handle's and the hand's, 1.5 N s/m):
        // lag = (F_c + b v) / k_grip
        assertEquals((coulomb + 1.5 * 0.05) / 300, lag[0], 0.1 * lag[0], "uncompensated lag");
        assertEquals((0.2 * coulomb + 1.5 * 0.05) / 300, lag[1], 0.1 * lag[1], "compensated lag: 80 % of F_c removed");
        // at rest, nothing is added: the handle held still stays where it is
        SampledPlant p = new SampledPlant(0.05, 0.5, T, 0).coulomb(coulomb);
        PortRig rig = new PortRig(p, new NoForceAvatar());
        rig.port.setFriction(new FrictionCompensation(0.8 * coulomb));
        rig.start(0);
        for (int i = 0; i < 1000; i++) {
            rig.tick();
            assertEquals(0, rig.sent, 0, "no force on a handle at rest");
        }
        assertEquals(0, p.x, 0);
    }

    @Test
    void settingsAreValidatedNamingTheValue() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new VirtualCoupling(-1, 0, 0.01))
                .getMessage().contains("-1"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new VirtualCoupling(100, 0, 0))
                .getMessage().contains("mass"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> VirtualCoupling.forDevice(0, T, 0))
                .getMessage().contains("damping"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new FrictionCompensation(Double.NaN))
                .getMessage().contains("NaN"));
        VirtualCoupling c = VirtualCoupling.forDevice(0.5, 1e-3, 0);
        // passive on the device: b > k T (d + 1/2) + c with a factor 2 of margin on k
        assertEquals(0.5, 2 * c.stiffness() * 1e-3 * 0.5 + c.damping(), 1e-12);
        assertFalse(c.mass() <= 0);
    }
}
