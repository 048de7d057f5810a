package tactus;

/**
 * The stability analysis of a {@link PhysicalModel}, as returned by {@link PhysicalModel#getStabilityReport()}.
 *
 * <p>The explicit scheme is stable when {@code lambda = λmax(M⁻¹(K + 2Z)) < 4}, where M, K and Z are the
 * network's mass, stiffness and damping matrices in per-step units (springs, dampers, oscillator springs, air
 * friction, and contacts counted as engaged). {@link #margin()} is {@code 4 - lambda}: positive means stable.
 * Negative damping is reported separately, since it is sometimes intended (a bowed or self-sustained
 * oscillation). The report is a snapshot: later changes to the model do not update it.
 */
public final class StabilityReport {
    /** The stability limit of {@code λmax(M⁻¹(K + 2Z))} for the explicit central-difference scheme. */
    public static final double LIMIT = 4.0;

    private final double lambda;
    private final double gershgorin;
    private final double lambdaLinks;
    private final double lambdaContacts;
    private final boolean converged;
    private final String culprit;
    private final String negativeDamping;

    StabilityReport(tactus.engine.StabilityReport r, String culprit, String negativeDamping) {
        this.lambda = r.lambda();
        this.gershgorin = r.gershgorinBound();
        this.lambdaLinks = r.lambdaLinks();
        this.lambdaContacts = r.lambdaContacts();
        this.converged = r.method() != tactus.engine.StabilityReport.Method.LANCZOS_UNCONVERGED;
        this.culprit = culprit;
        this.negativeDamping = negativeDamping;
    }

    /** {@return the estimate of {@code λmax(M⁻¹(K + 2Z))} used for the verdict (links plus contacts), per step²} */
    public double lambda() {
        return lambda;
    }

    /** {@return a guaranteed upper bound of {@code λmax(M⁻¹(K + 2Z))} from Gershgorin row sums} */
    public double gershgorinBound() {
        return gershgorin;
    }

    /** {@return the part of {@link #lambda()} due to permanent links, oscillators and friction} */
    public double lambdaLinks() {
        return lambdaLinks;
    }

    /** {@return the bound added for contacts counted as engaged} */
    public double lambdaContacts() {
        return lambdaContacts;
    }

    /** {@return {@code LIMIT - lambda}; positive means the scheme is stable for this network} */
    public double margin() {
        return LIMIT - lambda;
    }

    /** {@return true when the network is inside the stable region (negative damping aside)} */
    public boolean isStable() {
        return lambda < LIMIT;
    }

    /** {@return true when the eigenvalue iteration converged; otherwise {@link #gershgorinBound()} is the safe figure} */
    public boolean isConverged() {
        return converged;
    }

    /**
     * {@return the factor by which every stiffness and damping of the network could be multiplied and stay
     *     stable: {@code LIMIT / lambda} (infinite for a network with nothing that can go unstable)}
     */
    public double headroom() {
        return lambda > 0 ? LIMIT / lambda : Double.POSITIVE_INFINITY;
    }

    /**
     * {@return the module where the bound is tightest, as {@code Type "name"} (for example
     *     {@code SpringDamper3D "s12"} or {@code the contact group of subset "marbles"}), or null for a trivial
     *     network}
     */
    public String getCulprit() {
        return culprit;
    }

    /** {@return true when some damping coefficient is negative: oscillations are sustained or grow} */
    public boolean hasNegativeDamping() {
        return negativeDamping != null;
    }

    /** {@return the first module with negative damping, as {@code Type "name"}, or null} */
    public String getNegativeDampingModule() {
        return negativeDamping;
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT, "lambda=%.6g (links %.6g + contacts %.6g%s), margin=%.6g%s%s",
                lambda, lambdaLinks, lambdaContacts, converged ? "" : ", not converged", margin(),
                culprit == null ? "" : ", tightest at " + culprit,
                negativeDamping == null ? "" : ", negative damping at " + negativeDamping);
    }
}
