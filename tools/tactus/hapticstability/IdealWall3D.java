package tactus.hapticstability;

import tactus.haptics.emulator.PlantParameters;

/**
 * The reference for how still a handle can be on a frictionless plant: the case's press against an ideal wall, a
 * one-sided spring acting continuously (every substep, no sampling, no hold, no delay), with the same hand (the grip's
 * spring to the script and its damper on the handle's velocity, as {@code Hand3D.followingScript}) and the same
 * Cartesian plant (mass and damping, no friction), integrated at the plant's substep. Its residual is what no renderer
 * of that wall can beat: on a light-damped plant a stiff wall rings after a contact however it is rendered (for the
 * 0.2 kg, 0.5 N s/m plant and the pen grip, 4.1 µm at 3300 N/m and 7.0 µm at 8140 N/m; with a 0.4 kg handle, 9.4 µm at
 * 3300 N/m: past the suite's 5 µm).
 */
public final class IdealWall3D {
    private IdealWall3D() {
    }

    /**
     * The residual (m, as {@link AdversarialRig#residual}) of the press {@code c} (frictionless) against an ideal wall of
     * stiffness {@code k} (N/m) on the plant's mass and damping.
     *
     * @throws IllegalArgumentException if the case is not a press without friction, or k is not a number &gt; 0
     */
    public static double residual(AdversarialCase c, PlantParameters plant, double k) {
        if (c.kind != AdversarialCase.Kind.PRESS || c.friction || !(k > 0)) {
            throw new IllegalArgumentException("IdealWall3D.residual: give a press without friction and a stiffness > 0"
                    + " N/m, got " + c + " and " + k);
        }
        double m = plant.jointInertia() + plant.handleMass();
        double b = plant.jointDamping() + plant.taskDamping();
        double h = plant.substep();
        double[] xy = new double[2];
        tactus.haptics.emulator.Hand.Script script = c.script(0, 0, 0);
        int n = (int) Math.ceil(c.duration() / h);
        AdversarialRig.Record rec = new AdversarialRig.Record(n);
        double wall = -c.gap();
        double y = 0;
        double v = 0;
        for (int i = 0; i < n; i++) {
            double t = (i + 1) * h;
            script.at(t, xy);
            double hand = c.grip.stiffness * (xy[1] - y) - c.grip.damping * v;
            double push = y < wall ? k * (wall - y) : 0;
            v += (hand + push - b * v) / m * h;
            y += v * h;
            rec.t[i] = t;
            rec.y[i] = y;
        }
        rec.n = n;
        return AdversarialRig.residual(c, rec, wall);
    }
}
