package tactus.engine;

import static tactus.engine.LinkKind.Flag.CONDITIONAL;
import static tactus.engine.LinkKind.Flag.DAMPED;
import static tactus.engine.LinkKind.Flag.LENGTH;
import static tactus.engine.LinkKind.Flag.NO_HISTORY;
import static tactus.engine.LinkKind.Flag.ONE_D;
import static tactus.engine.LinkKind.Flag.SINGLE;
import static tactus.engine.LinkKind.Flag.STIFF;

/**
 * The kinds of interaction module, each one the single descriptor of its kind: its name, its parameters and their
 * units, its flat-array kernel, how its tension is read, how it is drawn by default, its mi.lib function for the
 * Faust export, its potential energy and what the stability check may assume of it. The declaration order is the
 * order in which a compiled {@link StepPlan} runs their kernels; within one kind, links run in insertion order.
 *
 * <p>Every kind has the three common parameters (stiffness K, damping Z, length) when its flags say so, and up to
 * two more, named by {@link #auxNames()}, whose units {@link #auxUnits()} gives. The rooms that may not import the
 * engine read this descriptor through the public {@code tactus.linkModuleType}, which delegates here.
 */
public enum LinkKind {
    /** Linear spring on the distance between two masses: f = -K (d - l0). */
    SPRING3D("Spring3D", STIFF | LENGTH, LinkKernels.Spring::new, Engagement.ALWAYS, 0xFF1E6464, null),
    /** Radial damper: f = -Z (d(n) - d(n-1)). */
    DAMPER3D("Damper3D", DAMPED, LinkKernels.Damper::new, Engagement.ALWAYS, 0xFF1E6464, null),
    /** Spring and damper in parallel. */
    SPRING_DAMPER3D("SpringDamper3D", STIFF | DAMPED | LENGTH, LinkKernels.SpringDamper::new, Engagement.ALWAYS,
            0xFF1EFAFA, null),
    /** Spring and damper acting along z only, on the signed difference z1 - z2. */
    SPRING_DAMPER1D("SpringDamper1D", STIFF | DAMPED | LENGTH | ONE_D, LinkKernels.SpringDamper1D::new,
            Engagement.ALWAYS, 0xFF32FFFA, "springDamper(K, Z)"),
    /** Spring-damper that acts only while stretched beyond its rest length. */
    ROPE3D("Rope3D", STIFF | DAMPED | LENGTH | CONDITIONAL, LinkKernels.Stretched::new, Engagement.WHEN_STRETCHED,
            0xFF00FF64, null),
    /** Spring-damper that acts only while the masses are closer than a threshold. */
    CONTACT3D("Contact3D", STIFF | DAMPED | LENGTH | CONDITIONAL, LinkKernels.Proximity::new,
            Engagement.WHEN_COMPRESSED, 0x00FF6464, "collision(K, Z, dist)"),
    /** Spring-damper that acts only while the masses are farther apart than a radius. */
    BUBBLE3D("Bubble3D", STIFF | DAMPED | LENGTH | CONDITIONAL, LinkKernels.Stretched::new, Engagement.WHEN_STRETCHED,
            0x001E6464, null),
    /** One-sided spring-damper between one mass and an axis-aligned plane. */
    PLANE_CONTACT3D("PlaneContact3D", STIFF | DAMPED | LENGTH | CONDITIONAL | SINGLE | NO_HISTORY,
            LinkKernels.Plane::new, Engagement.NONE, 0x007D7D7D, "collision(K, Z, dist)"),
    /** Inverse-square attraction beyond a limit distance: f = -A / d^2. */
    ATTRACTOR3D("Attractor3D", LENGTH | NO_HISTORY, LinkKernels.Attractor::new, Engagement.NONE, 0x007D7D7D, null),

    /** mi.lib's nlSpringDamper2 along the distance: F = K e + Q sgn(e) e^2 + Z v, e = d - l0. */
    QUADRATIC_SPRING_DAMPER3D("QuadraticSpringDamper3D", STIFF | DAMPED | LENGTH, NonlinearKernels.Elastic3D::new,
            Engagement.ALWAYS, 0xFFFAC81E, "nlSpringDamper2(K, Q, Z)", new String[] {"Q"}, ParamUnit.STIFFNESS),
    /** mi.lib's nlSpringDamper2 along z: F = K e + Q sgn(e) e^2 + Z v, e = z1 - z2 - l0. */
    QUADRATIC_SPRING_DAMPER1D("QuadraticSpringDamper1D", STIFF | DAMPED | LENGTH | ONE_D,
            NonlinearKernels.Elastic1D::new, Engagement.ALWAYS, 0xFFFAC81E, "nlSpringDamper2(K, Q, Z)",
            new String[] {"Q"}, ParamUnit.STIFFNESS),
    /** mi.lib's nlSpringDamper3 along the distance: F = K e + Q e^3 + Z v. */
    CUBIC_SPRING_DAMPER3D("CubicSpringDamper3D", STIFF | DAMPED | LENGTH, NonlinearKernels.Elastic3D::new,
            Engagement.ALWAYS, 0xFFFA961E, "nlSpringDamper3(K, Q, Z)", new String[] {"Q"}, ParamUnit.STIFFNESS),
    /** mi.lib's nlSpringDamper3 along z. */
    CUBIC_SPRING_DAMPER1D("CubicSpringDamper1D", STIFF | DAMPED | LENGTH | ONE_D, NonlinearKernels.Elastic1D::new,
            Engagement.ALWAYS, 0xFFFA961E, "nlSpringDamper3(K, Q, Z)", new String[] {"Q"}, ParamUnit.STIFFNESS),
    /** mi.lib's nlSpringDamperClipped along the distance: a cubic spring bounded by the stiffness Kmax. */
    CLIPPED_SPRING_DAMPER3D("ClippedSpringDamper3D", STIFF | DAMPED | LENGTH, NonlinearKernels.Elastic3D::new,
            Engagement.ALWAYS, 0xFFFA641E, "nlSpringDamperClipped(K, C, Kmax, Z)", new String[] {"C", "Kmax"},
            ParamUnit.STIFFNESS, ParamUnit.STIFFNESS),
    /** mi.lib's nlSpringDamperClipped along z. */
    CLIPPED_SPRING_DAMPER1D("ClippedSpringDamper1D", STIFF | DAMPED | LENGTH | ONE_D,
            NonlinearKernels.Elastic1D::new, Engagement.ALWAYS, 0xFFFA641E, "nlSpringDamperClipped(K, C, Kmax, Z)",
            new String[] {"C", "Kmax"}, ParamUnit.STIFFNESS, ParamUnit.STIFFNESS),
    /** mi.lib's nlPluck along the distance: a repulsive spring that lets go past its distance scale. */
    PLUCK3D("Pluck3D", STIFF | DAMPED | LENGTH, NonlinearKernels.Elastic3D::new, Engagement.ALWAYS, 0xFFC83CC8,
            "nlPluck(K, scale, Z)", new String[] {"scale"}, ParamUnit.LENGTH),
    /** mi.lib's nlPluck along z. */
    PLUCK1D("Pluck1D", STIFF | DAMPED | LENGTH | ONE_D, NonlinearKernels.Elastic1D::new, Engagement.ALWAYS,
            0xFFC83CC8, "nlPluck(K, scale, Z)", new String[] {"scale"}, ParamUnit.LENGTH),
    /** mi.lib's nlBow on the relative velocity vector: stick-slip friction. */
    BOW3D("Bow3D", DAMPED | NO_HISTORY, NonlinearKernels.Bow3D::new, Engagement.ALWAYS, 0xFFE6B450, null,
            new String[] {"scale", "profile"}, ParamUnit.VELOCITY, ParamUnit.NUMBER),
    /** mi.lib's nlBow along z. */
    BOW1D("Bow1D", DAMPED | ONE_D | NO_HISTORY, NonlinearKernels.Bow1D::new, Engagement.ALWAYS, 0xFFE6B450,
            "nlBow(Z, scale, profile)", new String[] {"scale", "profile"}, ParamUnit.VELOCITY, ParamUnit.NUMBER),
    /** mi.lib's nlCollisionClipped on the distance: a clipped cubic contact while d is below the threshold. */
    CLIPPED_CONTACT3D("ClippedContact3D", STIFF | DAMPED | LENGTH | CONDITIONAL, NonlinearKernels.Contact3D::new,
            Engagement.WHEN_COMPRESSED, 0x00FF3232, "nlCollisionClipped(K, C, Kmax, Z, dist)",
            new String[] {"C", "Kmax"}, ParamUnit.STIFFNESS, ParamUnit.STIFFNESS),
    /** mi.lib's nlCollisionClipped along z, mass 2 above mass 1: acts while z2 - z1 is below the threshold. */
    CLIPPED_CONTACT1D("ClippedContact1D", STIFF | DAMPED | LENGTH | ONE_D, NonlinearKernels.Contact1D::new,
            Engagement.WHEN_COMPRESSED, 0x00FF3232, "nlCollisionClipped(K, C, Kmax, Z, dist)", new String[] {"C", "Kmax"},
            ParamUnit.STIFFNESS, ParamUnit.STIFFNESS);

    /** How the tension of a link is read by a listening point that asks for its force. */
    public enum Engagement {
        /** The link always acts: its elongation is its tension. */
        ALWAYS,
        /** The link acts only while its masses are closer than its length. */
        WHEN_COMPRESSED,
        /** The link acts only while its masses are farther apart than its length. */
        WHEN_STRETCHED,
        /** The tension of the link cannot be read. */
        NONE
    }

    /** The unit class of a parameter, which says how it converts between REAL_UNITS and per-step values. */
    public enum ParamUnit {
        /** A stiffness or any force per power of length (N/m, N/m^2, N/m^3): scaled by fs^2. */
        STIFFNESS,
        /** A damping (N·s/m): scaled by fs. */
        DAMPING,
        /** A length (m): not scaled. */
        LENGTH,
        /** A velocity (m/s in REAL_UNITS, a displacement per step in ALGO_UNITS): scaled by 1/fs. */
        VELOCITY,
        /** A pure number: not scaled. */
        NUMBER
    }

    /** Makes the kernel that steps one batch of links of a kind. */
    @FunctionalInterface
    interface KernelFactory {
        Kernel create(LinkBatch b, StepPlan p);
    }

    private final String label;
    private final int flags;
    private final KernelFactory kernel;
    private final Engagement engagement;
    private final int color;
    private final String miLib;
    private final String[] auxNames;
    private final ParamUnit[] auxUnits;

    LinkKind(String label, int flags, KernelFactory kernel, Engagement engagement, int color, String miLib) {
        this(label, flags, kernel, engagement, color, miLib, new String[0]);
    }

    LinkKind(String label, int flags, KernelFactory kernel, Engagement engagement, int color, String miLib,
             String[] auxNames, ParamUnit... auxUnits) {
        this.label = label;
        this.flags = flags;
        this.kernel = kernel;
        this.engagement = engagement;
        this.color = color;
        this.miLib = miLib;
        this.auxNames = auxNames;
        this.auxUnits = auxUnits;
    }

    /** {@return the module name used in the API, in model files and in messages, e.g. {@code "SpringDamper3D"}} */
    public String label() {
        return label;
    }

    /** {@return the kind whose {@link #label()} is {@code label}, or null when there is none} */
    public static LinkKind byLabel(String label) {
        for (LinkKind k : Every.KINDS) {
            if (k.label.equals(label)) {
                return k;
            }
        }
        return null;
    }

    /** {@return true when the kind has a stiffness parameter K} */
    public boolean hasStiffness() {
        return (flags & STIFF) != 0;
    }

    /** {@return true when the kind has a damping parameter Z} */
    public boolean hasDamping() {
        return (flags & DAMPED) != 0;
    }

    /**
     * {@return true when the kind has a length parameter: rest length (springs, 1D spring-damper, rope, pluck),
     * threshold (contacts), radius (bubble), offset (plane contact) or limit distance (attractor)}
     */
    public boolean hasLength() {
        return (flags & LENGTH) != 0;
    }

    /** {@return true when the kind acts on one mass only (the plane contact)} */
    public boolean isSingleMass() {
        return (flags & SINGLE) != 0;
    }

    /** {@return true when the force applies only under a distance condition and the damper then starts afresh} */
    public boolean isConditional() {
        return (flags & CONDITIONAL) != 0;
    }

    /** {@return true when the kind acts along z only, on the signed difference z1 - z2 (a 1-D module)} */
    public boolean isOneDimensional() {
        return (flags & ONE_D) != 0;
    }

    /** {@return true when the kind keeps a previous distance for its damper (false: plane, attractor, bows)} */
    public boolean keepsHistory() {
        return (flags & NO_HISTORY) == 0;
    }

    /** {@return how a listening point reads the tension of a link of this kind} */
    public Engagement engagement() {
        return engagement;
    }

    /** {@return the default colour of the kind in drawings, as 0xAARRGGBB (alpha 0: drawn without its line)} */
    public int color() {
        return color;
    }

    /**
     * {@return the name of the function of Faust's mi.lib whose law the kind applies (a 1-D kind exactly; a 3-D one
     * along the distance), or null}
     */
    public String miLibFunction() {
        return miLib == null ? null : miLib.substring(0, miLib.indexOf('('));
    }

    /**
     * {@return the parameters the mi.lib function takes before its initial positions, in its order, named as the kind
     * names them ({@code "K"}, {@code "Z"}, {@code "dist"} or one of {@link #auxNames()}); empty when the kind has no
     * mi.lib function}
     */
    public String[] miLibArguments() {
        if (miLib == null) {
            return new String[0];
        }
        return miLib.substring(miLib.indexOf('(') + 1, miLib.length() - 1).split(", ");
    }

    /**
     * {@return the power of the sampling rate that converts parameter {@code i} beyond K, Z and the length from
     * REAL_UNITS to per-step values (per step = real / fs^power): 2 for stiffnesses, 1 for dampings and velocities, 0
     * for lengths and numbers}
     */
    public int auxRatePower(int i) {
        switch (auxUnits[i]) {
            case STIFFNESS:
                return 2;
            case DAMPING:
            case VELOCITY:
                return 1;
            default:
                return 0;
        }
    }

    /** {@return the names of the kind's parameters beyond K, Z and the length (empty for most kinds)} */
    public String[] auxNames() {
        return auxNames.clone();
    }

    /** {@return the number of parameters beyond K, Z and the length} */
    public int auxCount() {
        return auxNames.length;
    }

    /** {@return the unit class of parameter {@code i} beyond K, Z and the length} */
    public ParamUnit auxUnit(int i) {
        return auxUnits[i];
    }

    /** {@return a copy of the unit classes of the parameters beyond K, Z and the length} */
    public ParamUnit[] auxUnits() {
        return auxUnits.clone();
    }

    /** {@return true when the kind's force law is one of mi.lib's nonlinear interactions} */
    public boolean isNonlinear() {
        return ordinal() >= QUADRATIC_SPRING_DAMPER3D.ordinal();
    }

    /** {@return the kernel that steps one batch of this kind} */
    Kernel kernel(LinkBatch b, StepPlan p) {
        return kernel.create(b, p);
    }

    /**
     * The potential energy of one nonlinear link (per-step units), from its current distance d (the signed z1 - z2
     * of a 1-D kind), or NaN for a kind whose energy the {@link EnergyMeter} computes itself or that has none.
     */
    double potential(double d, double k, double len, double aux0, double aux1) {
        switch (this) {
            case QUADRATIC_SPRING_DAMPER3D:
            case QUADRATIC_SPRING_DAMPER1D:
                return NonlinearLaws.quadraticPotential(k, aux0, d - len);
            case CUBIC_SPRING_DAMPER3D:
            case CUBIC_SPRING_DAMPER1D:
                return NonlinearLaws.cubicPotential(k, aux0, d - len);
            case CLIPPED_SPRING_DAMPER3D:
            case CLIPPED_SPRING_DAMPER1D:
                return NonlinearLaws.clippedPotential(k, aux0, aux1, d - len);
            case PLUCK3D:
            case PLUCK1D:
                return NonlinearLaws.pluckPotential(k, aux0, d - len);
            case BOW3D:
            case BOW1D:
                return 0;
            case CLIPPED_CONTACT3D:
                return d < len ? NonlinearLaws.clippedPotential(k, aux0, aux1, len - d) : 0;
            case CLIPPED_CONTACT1D:
                return -d < len ? NonlinearLaws.clippedPotential(k, aux0, aux1, d + len) : 0;
            default:
                return Double.NaN;
        }
    }

    /**
     * The stiffness the stability check assumes for one link: K for a linear kind, the largest slope the law
     * can reach for a bounded nonlinear one, and the linear part K for the quadratic and cubic springs, whose
     * slope grows without bound with the displacement (their check holds near rest only).
     */
    double boundStiffness(double k, double aux0, double aux1) {
        switch (this) {
            case CLIPPED_SPRING_DAMPER3D:
            case CLIPPED_SPRING_DAMPER1D:
            case CLIPPED_CONTACT3D:
            case CLIPPED_CONTACT1D:
                return NonlinearLaws.clippedStiffnessBound(k, aux0, aux1);
            case PLUCK3D:
            case PLUCK1D:
                return Math.abs(k - k / NonlinearLaws.PLUCK_SHARPNESS);
            default:
                return hasStiffness() ? k : 0;
        }
    }

    /** The damping the stability check assumes for one link: Z, or the largest slope of a nonlinear law. */
    double boundDamping(double k, double z, double aux0, double aux1) {
        switch (this) {
            case CLIPPED_SPRING_DAMPER3D:
            case CLIPPED_SPRING_DAMPER1D:
            case CLIPPED_CONTACT3D:
            case CLIPPED_CONTACT1D:
                // the clipped part adds mi.lib's over-damping 0.3 Kmax (only when the cubic term is on and K < Kmax)
                return aux0 != 0 && k < aux1 ? z + NonlinearLaws.CLIP_OVERDAMPING * aux1 : z;
            case BOW3D:
            case BOW1D:
                return NonlinearLaws.bowDampingBound(z, aux1);
            default:
                return hasDamping() ? z : 0;
        }
    }

    /** Every kind, in declaration order, without the copy {@code values()} makes. */
    private static final class Every {
        static final LinkKind[] KINDS = values();
    }

    /** The flags of a kind: which common parameters it has and how it acts. */
    static final class Flag {
        static final int STIFF = 1;
        static final int DAMPED = 2;
        static final int LENGTH = 4;
        static final int SINGLE = 8;
        static final int CONDITIONAL = 16;
        static final int ONE_D = 32;
        static final int NO_HISTORY = 64;

        private Flag() {
        }
    }
}
