package tactus.export;

/** Writes numbers as Faust literals: shortest round-trip decimal, lower-case exponent, negatives in brackets. */
final class FaustNumbers {
    private FaustNumbers() {
    }

    /** @return {@code v} as a Faust literal that parses back to the same double */
    static String lit(double v) {
        if (!Double.isFinite(v)) {
            throw new IllegalStateException("Faust export: non-finite value " + v);
        }
        if (v == 0) {
            return "0.0";
        }
        String s = Double.toString(Math.abs(v)).replace('E', 'e');
        return v < 0 ? "(-" + s + ")" : s;
    }
}
