package tactus.internal.stability;

import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.engine.StabilityAnalyzer;
import tactus.engine.StabilityReport;
import tactus.engine.StepPlan;
import tactus.internal.model.Directory;
import tactus.internal.model.Registry;
import tactus.internal.model.UnitScale;

/** Formats stability reports as one readable line, with module names and model units. */
public final class StabilityMessages {
    /** The factor by which the second analysis of a stiffness limit raises the culprit's stiffness. */
    private static final double PROBE = 1.01;

    private StabilityMessages() {
    }

    /**
     * @param p the plan the report was made from (read only)
     * @return a one-line description of an unstable report, or null if it is stable without negative damping
     */
    public static String describe(StabilityReport r, StepPlan p, Engine e, Directory dir, UnitScale u, int contacts,
                           String[] groupNames) {
        Registry mats = dir.mats;
        Registry links = dir.links;
        if (r.isStable()) {
            if (r.hasNegativeDamping()) {
                return negativeDamping(r, e, mats, links, u);
            }
            return null;
        }
        String where;
        double scale = StabilityReport.LIMIT / r.lambda();
        if (r.culpritLink() >= 0 && e.isLink(r.culpritLink())) {
            int id = r.culpritLink();
            LinkKind k = e.linkKind(id);
            String param;
            double value;
            double limit;
            if (!k.hasStiffness() && k.hasDamping()) {
                param = "Z";
                value = u.dampingOut(e.linkDamping(id));
                limit = value * scale;
            } else if (k == LinkKind.ATTRACTOR3D) {
                param = "attraction";
                value = u.forceOut(e.attraction(id));
                limit = value * scale;
            } else {
                param = "K";
                double kk = e.linkStiffness(id);
                limit = u.stiffnessOut(linearLimit(r, p, contacts, kk,
                        StabilityAnalyzer.Assumption.linkStiffness(id, kk * PROBE)));
                value = u.stiffnessOut(kk);
            }
            String unit = unit(param, u);
            where = k.label() + " \"" + links.name(id) + "\": " + param + " = " + fmt(value)
                    + (limit > 0 ? " is above its limit of about " + fmt(limit) + unit
                    : unit + " is too high, and lowering it alone cannot make the model stable")
                    + ". Fix: " + (limit > 0 ? "lower " + param + " below " + fmt(limit) : "lower the stiffness of the"
                    + " links around it") + ", raise the masses it joins, or " + moreSteps(param, u);
        } else if (r.culpritGroup() >= 0 && r.culpritGroup() < groupNames.length) {
            String g = groupNames[r.culpritGroup()];
            where = "the contact group of subset \"" + g + "\": its stiffness and damping are too high for "
                    + contacts + " simultaneous contacts per mass (lower K, raise the masses, or set "
                    + "setMaxContactsPerMass to the real packing)";
        } else if (r.culpritMass() >= 0 && e.isMass(r.culpritMass())) {
            int id = r.culpritMass();
            if (e.massKind(id).isOscillator()) {
                double kk = e.oscStiffness(id);
                double k = u.stiffnessOut(kk);
                double limit = u.stiffnessOut(linearLimit(r, p, contacts, kk,
                        StabilityAnalyzer.Assumption.oscillatorStiffness(id, kk * PROBE)));
                where = e.massKind(id).label() + " \"" + mats.name(id) + "\": K = " + fmt(k)
                        + (limit > 0 ? " is above its limit of about " + fmt(limit) + unit("K", u)
                        : unit("K", u) + " is too high, and lowering it alone cannot make the model stable (lower its"
                        + " damping Z)") + ". Fix: " + (limit > 0 ? "lower K below " + fmt(limit) + ", " : "")
                        + "raise its mass, or " + moreSteps("K", u);
            } else {
                where = e.massKind(id).label() + " \"" + mats.name(id) + "\": mass = " + fmt(e.mass(id))
                        + " is below its limit of about " + fmt(e.mass(id) / scale) + " (air friction). Fix: raise"
                        + " its mass, or lower the air friction (setFriction)";
            }
        } else {
            where = "the model";
        }
        return "Tactus: unstable model: " + where + " (stability index " + fmt(r.lambda()) + ", which must stay below 4"
                + (r.lambdaContacts() > 0 ? "; contacts counted as engaged add " + fmt(r.lambdaContacts()) : "")
                + "; docs/stability.md)";
    }

    /** @return the unit of a link or oscillator parameter in the model's units, with a leading space, or "". */
    static String unit(String param, UnitScale u) {
        if (!u.isReal()) {
            return " (model units)";
        }
        switch (param) {
            case "K":
                return " N/m";
            case "Z":
                return " N·s/m";
            default:
                return " N";
        }
    }

    /**
     * @return the third fix of a stiffness or damping above its limit: more steps per frame, said for the unit system
     *     (in real units a higher rate raises the limit; in model units the coefficients are per step, so the same
     *     motion at more steps per frame needs them lowered)
     */
    static String moreSteps(String param, UnitScale u) {
        if (u.isReal()) {
            return "take more steps per frame (a higher simulation rate, setSimRate, raises the limit of " + param
                    + (param.equals("Z") ? " in proportion)" : " with its square)");
        }
        return "take more steps per frame with " + param + (param.equals("Z") ? " divided by the factor" : " divided"
                + " by the factor's square") + " (the same motion per frame, further from the limit)";
    }

    /**
     * The value of one stiffness at which lambda reaches the limit, by linear extrapolation from a second
     * analysis that assumes that stiffness {@link #PROBE} times higher (exact for a single mass). The second
     * analysis only reads the plan: the engine is never written, so a realtime owner stepping the model (and a
     * ramp it runs) is never disturbed by a reader asking for this message.
     *
     * @param probe the stiffness {@code value * PROBE} to assume, on the culprit module
     */
    private static double linearLimit(StabilityReport r, StepPlan p, int contacts, double value,
                                      StabilityAnalyzer.Assumption probe) {
        double probed = value * PROBE;
        double l2 = StabilityAnalyzer.analyze(p, contacts, probe).lambda();
        double slope = (l2 - r.lambda()) / (probed - value);
        return slope > 0 ? value + (StabilityReport.LIMIT - r.lambda()) / slope : value * StabilityReport.LIMIT / r.lambda();
    }

    /** @return the module where the bound is tightest, as {@code Type "name"}, or null. */
    public static String culprit(StabilityReport r, Engine e, Directory dir, String[] groupNames) {
        if (r.culpritLink() >= 0 && e.isLink(r.culpritLink())) {
            return e.linkKind(r.culpritLink()).label() + " \"" + dir.linkName(r.culpritLink()) + "\"";
        }
        if (r.culpritGroup() >= 0 && r.culpritGroup() < groupNames.length) {
            return "the contact group of subset \"" + groupNames[r.culpritGroup()] + "\"";
        }
        if (r.culpritMass() >= 0 && e.isMass(r.culpritMass())) {
            return dir.describeMass(r.culpritMass());
        }
        return null;
    }

    /**
     * The suspect of a divergence, from the analysis of the diverged model.
     *
     * @param described the line of {@link #describe} for the report (null when stable without negative damping)
     * @param culprit the module where the bound is tightest ({@link #culprit}), or null
     * @return the unstable module with its parameter, limit and fix; or the module with negative damping; or, for a
     *     model that is linearly stable, the module closest to its limit and the other causes to look for
     */
    public static String suspect(StabilityReport r, String described, String culprit) {
        if (described != null) {
            return described.replaceFirst("^Tactus: (unstable model|negative damping): ", "");
        }
        return "no module is above its stability limit (the closest is " + (culprit != null ? culprit : "none")
                + String.format(java.util.Locale.ROOT, ", at %.0f %%", 100 * r.lambda() / StabilityReport.LIMIT)
                + " of the bound), so look at what drives the mass: a large force or velocity set from outside "
                + "(triggerForceImpulse, setMatVelocity, a haptic or position input), a contact pressed too deep, or a "
                + "parameter changed while the model steps";
    }

    /** @return the first module with negative damping, as {@code Type "name"}, or null. */
    public static String negativeDampingModule(StabilityReport r, Engine e, Directory dir) {
        if (r.negativeDampingLink() >= 0 && e.isLink(r.negativeDampingLink())) {
            return e.linkKind(r.negativeDampingLink()).label() + " \"" + dir.linkName(r.negativeDampingLink()) + "\"";
        }
        if (r.negativeDampingMass() >= 0 && e.isMass(r.negativeDampingMass())) {
            return dir.describeMass(r.negativeDampingMass());
        }
        return null;
    }

    private static String negativeDamping(StabilityReport r, Engine e, Registry mats, Registry links, UnitScale u) {
        if (r.negativeDampingLink() >= 0) {
            int id = r.negativeDampingLink();
            return "Tactus: negative damping: " + e.linkKind(id).label() + " \"" + links.name(id) + "\": Z = "
                    + fmt(u.dampingOut(e.linkDamping(id)))
                    + " < 0 feeds energy in; oscillations are sustained or grow (fine if intended, e.g. bowing)";
        }
        int id = r.negativeDampingMass();
        return "Tactus: negative damping: " + e.massKind(id).label() + " \"" + mats.name(id)
                + "\": damping plus air friction < 0 feeds energy in; oscillations are sustained or grow";
    }

    private static String fmt(double v) {
        return String.format(java.util.Locale.ROOT, "%.4g", v);
    }
}
