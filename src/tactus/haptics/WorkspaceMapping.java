package tactus.haptics;

import java.util.Arrays;

/**
 * How a device's position in metres maps into a model's space, and how a model force maps back onto the
 * device: an axis permutation with signs (which may change handedness), a scale (model units per metre) and an
 * offset (model units). Immutable; the {@code with...} methods return new mappings.
 *
 * <pre>
 * model[i] = sign[i] * scale * device[axis[i]] + offset[i]
 * deviceForce[axis[i]] = sign[i] * signum(scale) * gain * modelForce[i]      (newtons, gain in N per model force unit)
 * </pre>
 *
 * The force goes back along exactly the axes the position came from, so a mapping never makes a passive model
 * active, whatever its signs or handedness. Axes are written as a spec such as {@code "x,-z,y"}: model x is
 * device x, model y is minus device z, model z is device y.
 */
public final class WorkspaceMapping {
    private final int[] axis;
    private final double[] sign;
    private final double scale;
    private final double[] offset;

    private WorkspaceMapping(int[] axis, double[] sign, double scale, double[] offset) {
        this.axis = axis;
        this.sign = sign;
        this.scale = scale;
        this.offset = offset;
    }

    /** Model axes = device axes, scale 1 (metres), no offset. */
    public static WorkspaceMapping identity() {
        return of("x,y,z");
    }

    /**
     * A mapping from a spec of three comma-separated device axes, each optionally signed: {@code "x,-z,y"} makes
     * model x = device x, model y = -device z, model z = device y. Scale 1, no offset. Each of x, y, z must
     * appear once.
     */
    public static WorkspaceMapping of(String spec) {
        if (spec == null) {
            throw new IllegalArgumentException("WorkspaceMapping.of: spec must not be null");
        }
        String[] parts = spec.split(",");
        if (parts.length != 3) {
            throw new IllegalArgumentException("WorkspaceMapping.of: expected three axes like \"x,-z,y\", got \"" + spec + "\"");
        }
        int[] axis = new int[3];
        double[] sign = new double[3];
        boolean[] seen = new boolean[3];
        for (int i = 0; i < 3; i++) {
            String p = parts[i].trim().toLowerCase();
            double s = 1;
            if (p.startsWith("-")) {
                s = -1;
                p = p.substring(1).trim();
            } else if (p.startsWith("+")) {
                p = p.substring(1).trim();
            }
            int a = "x".equals(p) ? 0 : "y".equals(p) ? 1 : "z".equals(p) ? 2 : -1;
            if (a < 0 || seen[a]) {
                throw new IllegalArgumentException("WorkspaceMapping.of: each of x, y, z must appear once, got \"" + spec + "\"");
            }
            seen[a] = true;
            axis[i] = a;
            sign[i] = s;
        }
        return new WorkspaceMapping(axis, sign, 1, new double[3]);
    }

    /**
     * The default for the Inverse3 family into a model whose y points up (a REAL_UNITS model with gravity along
     * -y): model x = device x, model y = device z (up), model z = -device y (towards the user). Right-handed to
     * right-handed. The device axes are taken from Haply's documentation: x to the right, y away from the user,
     * z up, seen from the user; not checked on hardware.
     */
    public static WorkspaceMapping inverse3YUp() {
        return of("x,z,-y");
    }

    /**
     * The default for the Inverse3 family into Processing's screen space (x right, y down, z towards the
     * viewer): model x = device x, model y = -device z, model z = -device y. This flips handedness, as
     * Processing's screen space is left-handed.
     */
    public static WorkspaceMapping inverse3Screen() {
        return of("x,-z,-y");
    }

    /**
     * The default for a planar pantograph, as the paper's sketches: model x = -device x (the device seen from
     * the user), model y = device y, model z = device z (always 0).
     */
    public static WorkspaceMapping pantograph() {
        return of("-x,y,z");
    }

    /** The same axes with this scale (model units per metre, finite and non-zero). */
    public WorkspaceMapping withScale(double unitsPerMetre) {
        if (!Double.isFinite(unitsPerMetre) || unitsPerMetre == 0) {
            throw new IllegalArgumentException("WorkspaceMapping.withScale: scale must be finite and non-zero, got " + unitsPerMetre);
        }
        return new WorkspaceMapping(axis, sign, unitsPerMetre, offset);
    }

    /** The same axes and scale with this offset (model units, finite): where the device origin lands in the model. */
    public WorkspaceMapping withOffset(double x, double y, double z) {
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z)) {
            throw new IllegalArgumentException("WorkspaceMapping.withOffset: must be finite, got (" + x + ", " + y + ", " + z + ")");
        }
        return new WorkspaceMapping(axis, sign, scale, new double[] {x, y, z});
    }

    /**
     * The same axes and scale with the offset that puts this device point (metres) at this model point (model
     * units): for example the workspace centre at the model's origin.
     */
    public WorkspaceMapping centring(double[] devicePoint, double mx, double my, double mz) {
        double[] m = new double[3];
        new WorkspaceMapping(axis, sign, scale, new double[3]).toModel(devicePoint, m);
        return withOffset(mx - m[0], my - m[1], mz - m[2]);
    }

    /** The same mapping with model axis i (0, 1, 2) mirrored. */
    public WorkspaceMapping mirrored(int modelAxis) {
        if (modelAxis < 0 || modelAxis > 2) {
            throw new IllegalArgumentException("WorkspaceMapping.mirrored: axis must be 0, 1 or 2, got " + modelAxis);
        }
        double[] s = sign.clone();
        s[modelAxis] = -s[modelAxis];
        double[] o = offset.clone();
        return new WorkspaceMapping(axis, s, scale, o);
    }

    /** Scale in model units per metre. */
    public double scale() {
        return scale;
    }

    /** The device axis (0 x, 1 y, 2 z) that model axis i comes from. */
    public int deviceAxis(int modelAxis) {
        return axis[modelAxis];
    }

    /** The sign (+1 or -1) of model axis i against its device axis (not counting the scale's sign). */
    public double sign(int modelAxis) {
        return sign[modelAxis];
    }

    /** The offset along model axis i, in model units. */
    public double offset(int modelAxis) {
        return offset[modelAxis];
    }

    /** True if the mapping keeps handedness (the signed permutation, times the scale's sign, has determinant +1). */
    public boolean keepsHandedness() {
        double det = permutationParity() * sign[0] * sign[1] * sign[2] * Math.signum(scale) * Math.signum(scale) * Math.signum(scale);
        return det > 0;
    }

    private double permutationParity() {
        int inversions = 0;
        for (int i = 0; i < 3; i++) {
            for (int j = i + 1; j < 3; j++) {
                if (axis[i] > axis[j]) {
                    inversions++;
                }
            }
        }
        return (inversions & 1) == 0 ? 1 : -1;
    }

    /** Maps a device position (metres, device[0..2]) to the model (model units, out[0..2]). No allocation. */
    public void toModel(double[] device, double[] out) {
        double d0 = device[axis[0]];
        double d1 = device[axis[1]];
        double d2 = device[axis[2]];
        out[0] = sign[0] * scale * d0 + offset[0];
        out[1] = sign[1] * scale * d1 + offset[1];
        out[2] = sign[2] * scale * d2 + offset[2];
    }

    /** The inverse of {@link #toModel}: the device position (metres) of a model point. No allocation. */
    public void toDevice(double[] model, double[] out) {
        double m0 = (model[0] - offset[0]) / (sign[0] * scale);
        double m1 = (model[1] - offset[1]) / (sign[1] * scale);
        double m2 = (model[2] - offset[2]) / (sign[2] * scale);
        out[axis[0]] = m0;
        out[axis[1]] = m1;
        out[axis[2]] = m2;
    }

    /**
     * Maps a model force (model units, modelForce[0..2]) to the device force in newtons (out[0..2], device axes),
     * gain in newtons per model force unit. No allocation.
     */
    public void forceToDevice(double[] modelForce, double gain, double[] out) {
        double g = Math.signum(scale) * gain;
        double f0 = sign[0] * g * modelForce[0];
        double f1 = sign[1] * g * modelForce[1];
        double f2 = sign[2] * g * modelForce[2];
        out[axis[0]] = f0;
        out[axis[1]] = f1;
        out[axis[2]] = f2;
    }

    /** The inverse of {@link #forceToDevice}: the model force (model units) that a device force (N) comes from. */
    public void forceToModel(double[] deviceForce, double gain, double[] out) {
        double g = Math.signum(scale) * gain;
        for (int i = 0; i < 3; i++) {
            out[i] = g == 0 ? 0 : deviceForce[axis[i]] / (sign[i] * g);
        }
    }

    /** The spec of the axes, e.g. "x,-z,y". */
    public String axes() {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < 3; i++) {
            if (i > 0) {
                b.append(',');
            }
            b.append(sign[i] < 0 ? "-" : "").append("xyz".charAt(axis[i]));
        }
        return b.toString();
    }

    @Override
    public String toString() {
        return "WorkspaceMapping[" + axes() + ", scale " + scale + " per m, offset " + Arrays.toString(offset) + "]";
    }
}
