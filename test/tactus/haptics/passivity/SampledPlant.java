package tactus.haptics.passivity;

import tactus.haptics.emulator.CartesianPlantKinematics;
import tactus.haptics.emulator.DevicePlant;
import tactus.haptics.emulator.PlantParameters;

/**
 * Test fixture: one axis of the emulator's {@link DevicePlant} (a prismatic joint: mass m, viscous damping b, optional
 * Coulomb friction with its static threshold) driven through a zero-order hold, the force acting d ticks after it is
 * sent, optionally held by a hand (a spring-damper to a scripted intended position; the hand's mass is part of m).
 * Advances 200 plant substeps per tick and integrates the work the device force does on the handle exactly, as the
 * reference for the observer. Deterministic, simulated time.
 */
final class SampledPlant {
    private static final int SUBSTEPS = 200;
    final double period;
    private final int delay;
    private final double mass;
    private final double damping;
    private double coulomb;
    private DevicePlant plant;
    private double handStiffness;
    private double handDamping;
    private double intended = Double.NaN;   // NaN: no hand
    private final double[] command = new double[1];
    private final double[] hand = new double[1];
    private double startX;
    private double startV;
    /** Handle position (m) and velocity (m/s); set x and v before the first tick for the initial state. */
    double x;
    double v;
    /** Work (J) the device force has done on the handle: energy the device gave to the hand and handle. */
    double workOnHandle;

    SampledPlant(double mass, double damping, double period, int delayTicks) {
        this.mass = mass;
        this.damping = damping;
        this.period = period;
        this.delay = delayTicks;
    }

    SampledPlant coulomb(double newtons) {
        coulomb = newtons;
        return this;
    }

    SampledPlant hand(double stiffness, double damping) {
        handStiffness = stiffness;
        handDamping = damping;
        return this;
    }

    /** Where the hand wants the handle (m); NaN lets go. */
    void intend(double position) {
        intended = position;
    }

    private DevicePlant plant() {
        if (plant == null) {
            PlantParameters p = PlantParameters.cartesian3Dof().withoutFriction().withJointInertia(mass)
                    .withJointDamping(damping).withFriction(coulomb, coulomb).withSubstep(period / SUBSTEPS)
                    .withActuationDelay(delay * period);
            plant = new DevicePlant(p, new CartesianPlantKinematics(1), new double[] {x});
            startX = x;
            startV = v;
        }
        return plant;
    }

    /** Sends the force (N) computed this tick; it acts d ticks from now, for one tick. */
    void send(double force) {
        command[0] = force;
        plant().commandTorques(command);
    }

    /** Advances one tick. */
    void advance() {
        DevicePlant p = plant();
        double h = period / SUBSTEPS;
        for (int i = 0; i < SUBSTEPS; i++) {
            double before = p.q(0);
            double vel = p.qd(0);
            if (startV != 0) {   // the initial velocity: one push of m v0 over the first substep
                hand[0] = mass * startV / h;
                startV = 0;
            } else {
                hand[0] = Double.isNaN(intended) ? 0 : handStiffness * (intended - before) - handDamping * vel;
            }
            p.step(h, hand, 0);
            workOnHandle += p.motorTorque(0) * (p.q(0) - before);
        }
        x = p.q(0);
        v = p.qd(0);
    }

    /** The handle's displacement since the first tick, m. */
    double travelled() {
        return x - startX;
    }
}
