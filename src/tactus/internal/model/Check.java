package tactus.internal.model;

import tactus.Vect3D;

/** Argument validation at the API boundary, with messages that name the element and the value. */
public final class Check {
    private Check() {
    }

    public static IllegalArgumentException fail(String op, String element, String message) {
        return new IllegalArgumentException(op + "(\"" + element + "\"): " + message);
    }

    public static void name(String op, String name) {
        if (name == null || name.isEmpty()) {
            throw new IllegalArgumentException(op + ": the name must be a non-empty string, got "
                    + (name == null ? "null" : "\"\""));
        }
    }

    public static void finite(String op, String element, String param, double v) {
        if (!Double.isFinite(v)) {
            throw fail(op, element, param + " must be a finite number, got " + v);
        }
    }

    public static void positive(String op, String element, String param, double v) {
        if (!(v > 0) || !Double.isFinite(v)) {
            throw fail(op, element, param + " must be a finite number > 0, got " + v);
        }
    }

    public static void nonNegative(String op, String element, String param, double v) {
        if (!(v >= 0) || !Double.isFinite(v)) {
            throw fail(op, element, param + " must be a finite number >= 0, got " + v);
        }
    }

    /**
     * An attractor's limit distance must be finite and &gt; 0: its force A/d^2 is unbounded as d goes to 0, so
     * without a positive limit a close approach samples the singularity and flings the pair apart.
     */
    public static void attractorLimit(String op, String element, double dLim) {
        if (!(dLim > 0) || !Double.isFinite(dLim)) {
            throw fail(op, element, "an Attractor3D needs a limit distance dLim > 0 (its force A/d^2 is unbounded as"
                    + " d -> 0), got " + dLim);
        }
    }

    public static void vector(String op, String element, String param, Vect3D v) {
        if (v == null) {
            throw fail(op, element, param + " must not be null");
        }
        if (!v.isFinite()) {
            throw fail(op, element, param + " must have finite components, got " + v);
        }
    }
}
