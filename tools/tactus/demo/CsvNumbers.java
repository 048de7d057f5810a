package tactus.demo;

/**
 * Fast number formatting for the demo's CSV files, the same text as {@code String.format(Locale.ROOT, "%.Ne")}
 * and {@code "%.Nf"} (up to a rounding difference in the last digit, rarely), about twenty times faster: the
 * demo writes a few hundred thousand numbers, and {@code String.format} made that the slowest part of it.
 */
final class CsvNumbers {
    private static final long[] POW10 = new long[19];

    static {
        POW10[0] = 1;
        for (int i = 1; i < POW10.length; i++) {
            POW10[i] = POW10[i - 1] * 10;
        }
    }

    private CsvNumbers() {
    }

    /**
     * Appends {@code v} in scientific notation with {@code digits} digits after the point, as {@code %.<digits>e}
     * does: {@code -1.2345670e-03}. Non-finite values are written as {@code NaN}, {@code Infinity} or
     * {@code -Infinity}.
     *
     * @param digits 1 to 15
     */
    static StringBuilder scientific(StringBuilder out, double v, int digits) {
        if (!Double.isFinite(v)) {
            return out.append(v);
        }
        if (v < 0 || (v == 0 && 1 / v < 0)) {
            out.append('-');
            v = -v;
        }
        int exponent = 0;
        long mantissa = 0;
        if (v != 0) {
            exponent = (int) Math.floor(Math.log10(v));
            mantissa = Math.round(v / Math.pow(10, exponent) * POW10[digits]);
            if (mantissa >= 10 * POW10[digits]) {         // 9.99999995 rounded up to 10
                exponent++;
                mantissa = Math.round(v / Math.pow(10, exponent) * POW10[digits]);
            } else if (mantissa < POW10[digits]) {        // log10 a hair too high
                exponent--;
                mantissa = Math.round(v / Math.pow(10, exponent) * POW10[digits]);
            }
        }
        out.append(mantissa / POW10[digits]).append('.');
        appendPadded(out, mantissa % POW10[digits], digits);
        out.append('e').append(exponent < 0 ? '-' : '+');
        int e = Math.abs(exponent);
        if (e < 10) {
            out.append('0');
        }
        return out.append(e);
    }

    /**
     * Appends {@code v} with {@code decimals} digits after the point, as {@code %.<decimals>f} does for values
     * below 10<sup>9</sup> in magnitude; larger or non-finite values go through {@code String.format}.
     *
     * @param decimals 0 to 9
     */
    static StringBuilder fixed(StringBuilder out, double v, int decimals) {
        if (!Double.isFinite(v) || Math.abs(v) >= 1e9) {
            return out.append(String.format(java.util.Locale.ROOT, "%." + decimals + "f", v));
        }
        long scaled = Math.round(Math.abs(v) * POW10[decimals]);
        if (v < 0 && scaled != 0) {
            out.append('-');
        }
        out.append(scaled / POW10[decimals]);
        if (decimals > 0) {
            out.append('.');
            appendPadded(out, scaled % POW10[decimals], decimals);
        }
        return out;
    }

    private static void appendPadded(StringBuilder out, long value, int width) {
        for (int w = width - 1; w > 0 && value < POW10[w]; w--) {
            out.append('0');
        }
        out.append(value);
    }
}
