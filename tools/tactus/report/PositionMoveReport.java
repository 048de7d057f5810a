package tactus.report;

import java.io.File;
import java.util.Locale;
import tactus.PhysicalModel;
import tactus.StabilityPolicy;
import tactus.Vect3D;

/**
 * What {@link PhysicalModel#setMoveKeepsLinkHistory} changes in the paper's plucked string, where a plectrum
 * (a heavy mass held by three spring-dampers between three guide masses) is moved by {@code setMatPosition} on
 * every sample and plucks a string of 240 masses. The model and its parameters are those of the paper's
 * PluckedString sketch (44.1 kHz); the hand is scripted: resting below the string at (12, -3), then moved to
 * (12, 3) at sample 0, smoothed by the sketch's one-pole filter (0.01 per sample), so the plectrum crosses the
 * string once. The sound is the sketch's: the y position of mass "str4" × 1.4, high-passed by
 * {@code out = s - s_prev + 0.95 out}.
 *
 * <p>Prints the first differing sample, the levels over 0.5 s and their difference in dB, and draws both
 * waveforms into {@code docs/paper-pluck-move-history.png}. Run: {@code gradle positionMoveReport}.
 */
public final class PositionMoveReport {
    static final int FS = 44100;
    static final int SAMPLES = FS / 2;

    private PositionMoveReport() {
    }

    /** The paper's plucked string: guides, plectrum, 240 string masses between two fixed points, contacts. */
    static PhysicalModel pluckedString(boolean keepHistory) {
        PhysicalModel m = new PhysicalModel(FS, 60);
        m.setStabilityPolicy(StabilityPolicy.OFF);
        m.setMoveKeepsLinkHistory(keepHistory);
        m.setGravity(0);
        m.setFriction(0.00003);
        m.addMass2DPlane("guideM1", 1000000000, new Vect3D(2, -4, 0), new Vect3D(0, 2, 0));
        m.addMass2DPlane("guideM2", 1000000000, new Vect3D(4, -4, 0), new Vect3D(0, 2, 0));
        m.addMass2DPlane("guideM3", 1000000000, new Vect3D(3, -3, 0), new Vect3D(0, 2, 0));
        m.addMass3D("percMass", 100, new Vect3D(3, -4, 0), new Vect3D(0, 2, 0));
        for (int g = 1; g <= 3; g++) {
            m.addSpringDamper3D("test", 1, 1, 1, "guideM" + g, "percMass");
        }
        int n = 240;
        double spacing = 0.1;
        m.addGround3D("gnd0", new Vect3D(0, 0, 0));
        for (int i = 0; i < n; i++) {
            m.addMass2DPlane("str" + i, 1, new Vect3D(spacing * (i + 1), 0, 0), new Vect3D(0, 0, 0));
        }
        m.addGround3D("gnd1", new Vect3D(spacing * (n + 1), 0, 0));
        for (int i = 0; i < n - 1; i++) {
            m.addSpringDamper3D("sprd" + i, 0.02, 0.4, 0.01, "str" + i, "str" + (i + 1));
        }
        m.addSpringDamper3D("sprdg0", 0.02, 0.4, 0.01, "gnd0", "str0");
        m.addSpringDamper3D("sprdg1", 0.02, 0.4, 0.01, "gnd1", "str" + (n - 1));
        for (int i = 0; i < n; i++) {
            m.addContact3D("col", 0.5, 0.07, 0.01, "percMass", "str" + i);
        }
        m.addContact3D("col", 0.65, 10, 0.01, "percMass", "gnd0");
        m.addContact3D("col", 0.65, 10, 0.01, "percMass", "gnd1");
        m.init();
        return m;
    }

    /** The sketch's audio callback, sample by sample, with the scripted hand. */
    static double[] render(boolean keepHistory) {
        PhysicalModel m = pluckedString(keepHistory);
        double xAvg = 12;
        double yAvg = -3;
        double handX = 12;
        double handY = 3;
        double smooth = 0.01;
        // the hand rested below the string: place the guides there first, and let the plectrum settle
        for (int s = 0; s < FS / 10; s++) {
            moveGuides(m, xAvg, yAvg);
            m.computeStep();
        }
        double[] out = new double[SAMPLES];
        double prev = m.getMatPosition("str4").y * 1.4;
        double y = 0;
        for (int s = 0; s < SAMPLES; s++) {
            xAvg = (1 - smooth) * xAvg + smooth * handX;
            yAvg = (1 - smooth) * yAvg + smooth * handY;
            moveGuides(m, xAvg, yAvg);
            m.computeStep();
            double sample = m.getMatPosition("str4").y * 1.4;
            y = sample - prev + 0.95 * y;
            prev = sample;
            out[s] = y;
        }
        return out;
    }

    private static void moveGuides(PhysicalModel m, double x, double y) {
        m.setMatPosition("guideM1", new Vect3D(x - 1, y, 0));
        m.setMatPosition("guideM2", new Vect3D(x + 1, y, 0));
        m.setMatPosition("guideM3", new Vect3D(x, y - 1, 0));
    }

    static double rms(double[] a) {
        double s = 0;
        for (double v : a) {
            s += v * v;
        }
        return Math.sqrt(s / a.length);
    }

    public static void main(String[] args) {
        File png = new File(args.length > 0 ? args[0] : "docs/paper-pluck-move-history.png");
        double[] ours = render(false);
        double[] paper = render(true);
        int first = -1;
        double peakDiff = 0;
        for (int s = 0; s < SAMPLES; s++) {
            if (first < 0 && ours[s] != paper[s]) {
                first = s;
            }
            peakDiff = Math.max(peakDiff, Math.abs(ours[s] - paper[s]));
        }
        double rOurs = rms(ours);
        double rPaper = rms(paper);
        double[] diff = new double[SAMPLES];
        for (int s = 0; s < SAMPLES; s++) {
            diff[s] = ours[s] - paper[s];
        }
        System.out.println(String.format(Locale.ROOT,
                "first differing sample: %d%nRMS over 0.5 s: default %.6g, keep history %.6g; default is %.3f dB "
                        + "from keep history%npeak |difference| %.4g, RMS of the difference %.4g (%.2f dB below the "
                        + "keep-history signal)",
                first, rOurs, rPaper, 20 * Math.log10(rOurs / rPaper), peakDiff, rms(diff),
                20 * Math.log10(rPaper / rms(diff))));
        int shown = FS / 25;   // the first 40 ms
        double[] t = new double[shown];
        double[] a = new double[shown];
        double[] b = new double[shown];
        double[] d = new double[shown];
        for (int s = 0; s < shown; s++) {
            t[s] = 1000.0 * s / FS;
            a[s] = ours[s];
            b[s] = paper[s];
            d[s] = diff[s] - 1.2;   // drawn below the signals
        }
        new LineChart("Paper's plucked string: the first 40 ms after the hand moves", "time (ms)",
                "output (high-passed y of str4)")
                .series("setMoveKeepsLinkHistory(true), the paper's engine", t, b)
                .series("setMoveKeepsLinkHistory(false), Tactus's default", t, a)
                .series("difference (default - paper), offset by -1.2", t, d)
                .save(png, 900, 460);
        System.out.println("wrote " + png);
    }
}
