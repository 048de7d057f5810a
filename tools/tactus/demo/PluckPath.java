package tactus.demo;

import tactus.haptics.emulator.Hand;

/**
 * The scripted hand of the audio-haptic demo, in model units (the string lies along x from 0 to
 * {@link PluckScene#length()} at y = 0; y grows downwards on screen). From where the plectrum starts, the
 * hand glides above the string, pushes the plectrum slowly down through the string a quarter of the way
 * along it (the string is dragged down until it slips off the plectrum: a pluck), rests below, comes back up
 * through it (a second pluck, upwards), moves along, and strums: a fast diagonal stroke down through the
 * middle of the string. Then it rests below the string, out of reach, while the string rings.
 *
 * <p>Each move eases in and out ({@code (1 - cos(pi u)) / 2}), so the hand's speed is continuous.
 * {@link #deviceScript(DeviceMapping)} turns the path into the emulated hand's script in device
 * coordinates (metres).
 */
public final class PluckPath {
    /** Where the plucks happen along the string, model units (a quarter of its length). */
    public static final double PLUCK_X = 0.8;
    /** Height of the rests above and below the string, model units (far beyond the sphere of action). */
    public static final double CLEAR = 0.4;
    /** Where the strum starts, model units. */
    public static final double STRUM_FROM_X = 1.3;
    /** Where the strum ends, model units. */
    public static final double STRUM_TO_X = 1.9;
    /** Where the hand rests after the strum (below the string), model units. */
    public static final double FINAL_Y = 0.6;
    /** When the strum is over (the hand is then out of reach of the string), seconds. */
    public static final double STRUM_END = 2.75;
    /** Length of the whole script, seconds: the string rings freely from {@link #STRUM_END} to here. */
    public static final double DURATION = 4.5;

    /** The waypoints: time (s), x, y (model units); the hand eases from each to the next. */
    private final double[][] points;

    /**
     * @param startX where the plectrum is at time 0, model units
     * @param startY where the plectrum is at time 0, model units
     */
    public PluckPath(double startX, double startY) {
        points = new double[][] {
            {0.00, startX, startY},
            {0.30, PLUCK_X, -CLEAR},         // glide above the string
            {0.50, PLUCK_X, -CLEAR},         // rest
            {1.30, PLUCK_X, CLEAR},          // down through the string: pluck 1
            {1.50, PLUCK_X, CLEAR},          // rest below
            {2.30, PLUCK_X, -CLEAR},         // back up through it: pluck 2
            {2.60, STRUM_FROM_X, -CLEAR},    // move along, above
            {STRUM_END, STRUM_TO_X, FINAL_Y},  // strum: fast, down through the middle
            {DURATION, STRUM_TO_X, FINAL_Y}, // rest while the string rings
        };
    }

    /** @return the phase names of the script, one per move, for the plots and the printout. */
    public static String[] phases() {
        return new String[] {"glide", "rest", "pluck down", "rest", "pluck up", "move", "strum", "ring"};
    }

    /** The name of the move under way at time {@code t} (seconds into the script), one of {@link #phases()}. */
    public String phaseAt(double t) {
        String[] names = phases();
        int i = 0;
        while (i + 1 < points.length - 1 && t >= points[i + 1][0]) {
            i++;
        }
        return names[i];
    }

    /** @return the start times of the moves, seconds (same order as {@link #phases()}). */
    public double[] phaseStarts() {
        double[] t = new double[points.length - 1];
        for (int i = 0; i < t.length; i++) {
            t[i] = points[i][0];
        }
        return t;
    }

    /**
     * Writes the hand's position at time {@code t} (seconds; before 0 it is the start, after
     * {@link #DURATION} the end) into {@code out[0]} (x) and {@code out[1]} (y), model units.
     */
    public void at(double t, double[] out) {
        int last = points.length - 1;
        if (!(t > points[0][0])) {
            out[0] = points[0][1];
            out[1] = points[0][2];
            return;
        }
        for (int i = 0; i < last; i++) {
            double[] a = points[i];
            double[] b = points[i + 1];
            if (t < b[0]) {
                double u = (t - a[0]) / (b[0] - a[0]);
                double s = 0.5 * (1 - Math.cos(Math.PI * u));
                out[0] = a[1] + s * (b[1] - a[1]);
                out[1] = a[2] + s * (b[2] - a[2]);
                return;
            }
        }
        out[0] = points[last][1];
        out[1] = points[last][2];
    }

    /**
     * The path as the emulated hand's script: device coordinates in metres, through the inverse of the
     * haptic loop's mapping.
     */
    public Hand.Script deviceScript(DeviceMapping mapping) {
        double[] model = new double[2];
        return (t, out) -> {
            at(t, model);
            out[0] = mapping.deviceX(model[0]);
            out[1] = mapping.deviceY(model[1]);
        };
    }
}
