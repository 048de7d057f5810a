package tactus.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import java.util.Random;

import org.junit.jupiter.api.Test;

/** The demo's fast CSV formatting writes what String.format writes, up to a rare last-digit rounding difference. */
class CsvNumbersTest {

    @Test
    void scientificMatchesStringFormat() {
        Random rnd = new Random(42);
        int different = 0;
        int n = 200_000;
        for (int i = 0; i < n; i++) {
            double v = (rnd.nextBoolean() ? 1 : -1) * rnd.nextDouble() * Math.pow(10, rnd.nextInt(80) - 40);
            int digits = 1 + rnd.nextInt(9);
            String expected = String.format(Locale.ROOT, "%." + digits + "e", v);
            String actual = CsvNumbers.scientific(new StringBuilder(), v, digits).toString();
            if (!expected.equals(actual)) {
                different++;
                // then only the last digit may differ, by one unit
                double ulp = Math.abs(v) * Math.pow(10, -digits) * 1.0000001 * 10;
                assertEquals(Double.parseDouble(expected), Double.parseDouble(actual), ulp, expected + " vs " + actual);
                assertEquals(expected.length(), actual.length(), expected + " vs " + actual);
            }
        }
        assertTrue(different < n / 1000, different + " of " + n + " differ");
        for (double v : new double[] {0.0, -0.0, 1, -1, 9.99999995, 9.9999999, 1e-300, 4.9e-324, 1.7e308, 123456789,
            0.5, 1e-5, 99999.999995}) {
            String expected = String.format(Locale.ROOT, "%.7e", v);
            String actual = CsvNumbers.scientific(new StringBuilder(), v, 7).toString();
            assertEquals(Double.parseDouble(expected), Double.parseDouble(actual), Math.abs(v) * 2e-7, "" + v);
            assertEquals(expected.length(), actual.length(), expected + " vs " + actual);
        }
    }

    @Test
    void fixedMatchesStringFormat() {
        Random rnd = new Random(7);
        int different = 0;
        int n = 100_000;
        for (int i = 0; i < n; i++) {
            // up to 14 significant digits, as the demo's times (seconds with 6 to 8 decimals) have
            int decimals = rnd.nextInt(10);
            double v = (rnd.nextInt(4) == 0 ? -1 : 1) * rnd.nextDouble() * Math.pow(10, rnd.nextInt(14 - decimals));
            String expected = String.format(Locale.ROOT, "%." + decimals + "f", v);
            String actual = CsvNumbers.fixed(new StringBuilder(), v, decimals).toString();
            if (!expected.equals(actual)) {
                different++;
                assertEquals(Double.parseDouble(expected), Double.parseDouble(actual), 1.0001 * Math.pow(10, -decimals) + 4 * Math.ulp(v),
                        expected + " vs " + actual);
            }
        }
        // v * 10^decimals is rounded once before Math.round, so near-halfway values may end one unit apart
        assertTrue(different < n / 200, different + " of " + n + " differ");
        assertEquals("0.00000000", CsvNumbers.fixed(new StringBuilder(), 0, 8).toString());
        assertEquals("2.00000000", CsvNumbers.fixed(new StringBuilder(), 88200 / 44100.0, 8).toString());
        assertEquals("12", CsvNumbers.fixed(new StringBuilder(), 12.4, 0).toString());
    }
}
