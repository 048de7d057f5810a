package tactus.engine;

/**
 * Energy of a compiled scene in per-step units (multiply by fs^2 for joules).
 *
 * <p>Kinetic energy uses the backward-difference velocity, {@code ½ M |X(n) - X(n-1)|^2}, of
 * every inertial mass. Potential energy sums {@code ½ K e^2} over the elastic links that are
 * currently engaged (e the elongation, penetration or stretch), the oscillators' internal
 * springs, the attractors ({@code -A/d} beyond the limit) and gravity ({@code -M g·X}).
 * The scheme's exactly conserved quantity for undamped linear networks is given by
 * {@link #discreteEnergy(StepPlan)}.
 */
public final class EnergyMeter {
    private EnergyMeter() {
    }

    /** @return the kinetic energy of all inertial masses, per-step units. */
    public static double kinetic(StepPlan p) {
        double e = 0;
        for (int i = 0; i < p.nMass; i++) {
            double im = p.invM[i];
            if (im == 0) {
                continue;
            }
            double vx = p.x[i] - p.px[i], vy = p.y[i] - p.py[i], vz = p.z[i] - p.pz[i];
            e += 0.5 * (vx * vx + vy * vy + vz * vz) / im;
        }
        return e;
    }

    /** @return the potential energy stored in links, oscillators, attractors and gravity, per-step units. */
    public static double potential(StepPlan p) {
        double e = 0;
        for (int i = p.start(MassKind.OSC3D); i < p.end(MassKind.OSC1D); i++) {
            double ex = p.x[i] - p.restX[i], ey = p.y[i] - p.restY[i], ez = p.z[i] - p.restZ[i];
            e += 0.5 * (p.oscStiffnessPerMass[i] / p.invM[i]) * (ex * ex + ey * ey + ez * ez);
        }
        Medium m = p.medium;
        if (m.hasGravity()) {
            int simpleStart = p.start(MassKind.MASS3D_SIMPLE), simpleEnd = p.end(MassKind.MASS3D_SIMPLE);
            for (int i = 0; i < p.nMass; i++) {
                if (p.invM[i] != 0 && (i < simpleStart || i >= simpleEnd)) {
                    e -= (m.gx * p.x[i] + m.gy * p.y[i] + m.gz * p.z[i]) / p.invM[i];
                }
            }
        }
        for (LinkBatch b : p.batches) {
            if (b != null) {
                e += links(b, p);
            }
        }
        for (ContactGroupKernel g : p.groups) {
            e += g.energy();
        }
        return e;
    }

    private static double links(LinkBatch b, StepPlan p) {
        double e = 0;
        if (b.kind.isNonlinear()) {
            for (int j = 0; j < b.n; j++) {
                double a0 = b.aux0.length > 0 ? b.aux0[j] : 0, a1 = b.aux1.length > 0 ? b.aux1[j] : 0;
                e += b.kind.potential(PlanCompiler.distanceOf(b, j, p), b.k[j], b.len[j], a0, a1);
            }
            return e;
        }
        for (int j = 0; j < b.n; j++) {
            double stretch;
            switch (b.kind) {
                case PLANE_CONTACT3D: {
                    int axis = j < b.axisStart[1] ? 0 : j < b.axisStart[2] ? 1 : 2;
                    double[] q = axis == 0 ? p.x : axis == 1 ? p.y : p.z;
                    stretch = Math.min(0, q[b.a[j]] - b.planePosition[j] - b.len[j]);
                    break;
                }
                case ATTRACTOR3D: {
                    double r = Math.max(PlanCompiler.distanceOf(b, j, p), b.len[j]);
                    if (r > 0 && b.attraction[j] != 0) {
                        e -= b.attraction[j] / r;
                    }
                    continue;
                }
                case DAMPER3D:
                    continue;
                default: {
                    double d = PlanCompiler.distanceOf(b, j, p);
                    double x = d - b.len[j];
                    if (b.kind == LinkKind.CONTACT3D) {
                        x = Math.min(0, x);
                    } else if (b.kind == LinkKind.ROPE3D || b.kind == LinkKind.BUBBLE3D) {
                        x = Math.max(0, x);
                    }
                    stretch = x;
                }
            }
            e += 0.5 * b.k[j] * stretch * stretch;
        }
        return e;
    }

    /**
     * The scheme's discrete energy for undamped linear networks:
     * {@code ½ M |X(n) - X(n-1)|^2 + ½ K e(n) e(n-1)} summed over masses and springs, where e is
     * a spring's elongation. For a linear (1D, or 3D without rotation) undamped network this is
     * conserved to round-off by the explicit scheme. Only Spring3D, SpringDamper3D,
     * SpringDamper1D and oscillator terms are included.
     *
     * @return the discrete energy, per-step units
     */
    public static double discreteEnergy(StepPlan p) {
        double e = kinetic(p);
        for (int i = p.start(MassKind.OSC3D); i < p.end(MassKind.OSC1D); i++) {
            double k = p.oscStiffnessPerMass[i] / p.invM[i];
            e += 0.5 * k * ((p.x[i] - p.restX[i]) * (p.px[i] - p.restX[i])
                    + (p.y[i] - p.restY[i]) * (p.py[i] - p.restY[i])
                    + (p.z[i] - p.restZ[i]) * (p.pz[i] - p.restZ[i]));
        }
        for (LinkBatch b : p.batches) {
            if (b == null || !(b.kind == LinkKind.SPRING3D || b.kind == LinkKind.SPRING_DAMPER3D
                    || b.kind == LinkKind.SPRING_DAMPER1D)) {
                continue;
            }
            for (int j = 0; j < b.n; j++) {
                int a = b.a[j], c = b.b[j];
                double now;
                double before;
                if (b.kind == LinkKind.SPRING_DAMPER1D) {
                    now = p.z[a] - p.z[c];
                    before = p.pz[a] - p.pz[c];
                } else {
                    now = PlanCompiler.distanceOf(b, j, p);
                    double dx = p.px[a] - p.px[c], dy = p.py[a] - p.py[c], dz = p.pz[a] - p.pz[c];
                    before = Math.sqrt(dx * dx + dy * dy + dz * dz);
                }
                e += 0.5 * b.k[j] * (now - b.len[j]) * (before - b.len[j]);
            }
        }
        return e;
    }
}
