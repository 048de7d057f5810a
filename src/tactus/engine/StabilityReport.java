package tactus.engine;

/**
 * The result of a {@link StabilityAnalyzer} run, in per-step units.
 *
 * <p>The explicit scheme is stable when {@code λmax(M⁻¹(K + 2Z)) < 4}, where K and Z are the network's
 * stiffness and damping matrices (springs, dampers, oscillator springs, air friction, and contacts counted
 * as engaged). {@link #lambda()} is an upper estimate of that eigenvalue: the Lanczos estimate plus its
 * residual bound ({@link #lanczosResidual()}, the stated safety margin), plus the contact bound. The {@link #margin()} is {@code 4 - lambda}: positive means
 * stable. Negative damping is reported separately, since it is sometimes intended (a bowed or
 * self-sustained oscillation).
 */
public final class StabilityReport {
    /** How the largest eigenvalue was obtained. */
    public enum Method {
        /** No moving mass or no coupling: nothing can go unstable. */
        TRIVIAL,
        /**
         * Lanczos iteration on the sparse network, run until the residual of its largest Ritz value is below
         * 1e-7 relative: {@link #lambda()} is that Ritz value plus the residual.
         */
        LANCZOS,
        /**
         * Lanczos iteration stopped by its work budget before the residual reached 1e-7 relative:
         * {@link #lambda()} is still the Ritz value plus its (larger) residual, capped by
         * {@link #gershgorinBound()}, which is a guaranteed upper bound.
         */
        LANCZOS_UNCONVERGED
    }

    /** The stability limit of {@code λmax(M⁻¹(K + 2Z))} for the explicit central-difference scheme. */
    public static final double LIMIT = 4.0;

    private final double lambda;
    private final double gershgorin;
    private final double lambdaLinks;
    private final double lambdaContacts;
    private final Method method;
    private final int culpritLink;
    private final int culpritMass;
    private final int negativeDampingLink;
    private final int negativeDampingMass;
    private final int culpritGroup;
    private final double lanczosResidual;

    StabilityReport(double lambdaLinks, double lambdaContacts, double gershgorinLinks, Method method,
                    int culpritLink, int culpritMass, int negativeDampingLink,
                    int negativeDampingMass, int culpritGroup, double lanczosResidual) {
        this.culpritGroup = culpritGroup;
        this.lanczosResidual = lanczosResidual;
        this.lambda = lambdaLinks + lambdaContacts;
        this.gershgorin = gershgorinLinks + lambdaContacts;
        this.lambdaLinks = lambdaLinks;
        this.lambdaContacts = lambdaContacts;
        this.method = method;
        this.culpritLink = culpritLink;
        this.culpritMass = culpritMass;
        this.negativeDampingLink = negativeDampingLink;
        this.negativeDampingMass = negativeDampingMass;
    }

    /** @return the estimate of {@code λmax(M⁻¹(K + 2Z))} used for the verdict (links plus contacts). */
    public double lambda() {
        return lambda;
    }

    /**
     * @return a guaranteed upper bound of {@code λmax(M⁻¹(K + 2Z))} from Gershgorin row sums; never below
     *     {@link #lambda()} and at most about twice it for uniform networks.
     */
    public double gershgorinBound() {
        return gershgorin;
    }

    /**
     * @return the safety margin included in {@link #lambda()}: the residual {@code ||A y - theta y||} of the
     *     Lanczos Ritz value theta, which bounds how far below the largest eigenvalue theta may lie (0 when the
     *     network is trivial or the Krylov space was exhausted, where theta is exact)
     */
    public double lanczosResidual() {
        return lanczosResidual;
    }

    /** @return the part of {@link #lambda()} due to permanent links, oscillators and friction. */
    public double lambdaLinks() {
        return lambdaLinks;
    }

    /** @return the conservative bound added for contacts counted as engaged. */
    public double lambdaContacts() {
        return lambdaContacts;
    }

    /** @return {@code LIMIT - lambda}; positive means the scheme is stable for this network. */
    public double margin() {
        return LIMIT - lambda;
    }

    /** @return true when the network is inside the stable region (negative damping aside). */
    public boolean isStable() {
        return lambda < LIMIT;
    }

    /** @return how the eigenvalue was obtained. */
    public Method method() {
        return method;
    }

    /** @return the id of the link that contributes most where the bound is tightest, or -1. */
    public int culpritLink() {
        return culpritLink;
    }

    /** @return the id of the mass where the bound is tightest (an oscillator may itself be the culprit), or -1. */
    public int culpritMass() {
        return culpritMass;
    }

    /**
     * @return the index (in compiled order of the live contact groups) of the contact group that makes the
     *     bound tightest, or -1 when the culprit is not a contact group
     */
    public int culpritGroup() {
        return culpritGroup;
    }

    /** @return the id of the first link with negative damping, or -1. */
    public int negativeDampingLink() {
        return negativeDampingLink;
    }

    /** @return the id of the first oscillator with negative damping, or -1 (negative friction: see the facade). */
    public int negativeDampingMass() {
        return negativeDampingMass;
    }

    /** @return true when some damping coefficient is negative: oscillations are sustained or grow. */
    public boolean hasNegativeDamping() {
        return negativeDampingLink >= 0 || negativeDampingMass >= 0;
    }

    /**
     * @return the factor by which every stiffness and damping of the network could be multiplied and stay
     *     stable: {@code LIMIT / lambda} (infinite for a trivial network).
     */
    public double headroom() {
        return lambda > 0 ? LIMIT / lambda : Double.POSITIVE_INFINITY;
    }

    @Override
    public String toString() {
        return String.format("lambda=%.8g (links %.8g incl. Lanczos residual %.2g + contacts %.6g, %s), margin=%.6g%s",
                lambda, lambdaLinks, lanczosResidual, lambdaContacts, method, margin(),
                hasNegativeDamping() ? ", negative damping" : "");
    }
}
