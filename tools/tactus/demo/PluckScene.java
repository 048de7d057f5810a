package tactus.demo;

import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * The audio-haptic plucked string of the paper, as the demo builds it: a string of {@value #MASSES}
 * {@code Mass2DPlane} masses (they move in the x-y plane), {@value #SPACING} apart along x between two
 * {@code Ground3D}, joined by {@code SpringDamper3D} links whose length parameter ({@value #REST}) is
 * shorter than the spacing, so the string is under tension; and a plectrum, the {@code HapticInput3D}
 * "{@value #PLECTRUM}" that the Haply drives, with a {@code Contact3D} to every mass of the string. The
 * contact distance is the plectrum's sphere of action: every mass closer than {@value #SPHERE} to the
 * plectrum is pushed away, so a slow stroke drags the string until it slips off (a pluck), a plectrum held
 * on the string damps it (a palm mute), and a light touch at a node leaves only the modes that have a node
 * there (a natural harmonic).
 *
 * <p>Algorithmic units (per step), the paper's choice, at {@value #AUDIO_RATE} steps per second: the model
 * is stepped once per audio sample. For small sideways (y) motion a stretched link has the transverse
 * stiffness {@code kt = K (1 - l0 / d)}, and the explicit scheme gives mode m of N masses the discrete
 * frequency {@code cos w_m = 1 - 2 (kt / M) sin^2(m pi / (2 (N + 1)))} in radians per step
 * ({@link #modeHz(int)}).
 */
public final class PluckScene {
    /** Audio rate and model rate, steps per second. */
    public static final int AUDIO_RATE = 44100;
    /** Moving masses of the string. */
    public static final int MASSES = 30;
    /** Inertia of each mass (algorithmic units). */
    public static final double MASS = 1.0;
    /** Distance between neighbouring masses (and the ends) at rest, model units. */
    public static final double SPACING = 0.1;
    /** Length parameter of each link: half the spacing, so the string is stretched. */
    public static final double REST = 0.05;
    /** Stiffness of each link, per step squared. */
    public static final double STIFFNESS = 0.2;
    /** Damping of each link, per step (it acts along the link). */
    public static final double DAMPING = 0.0001;
    /** Air friction of the model, per step: the string rings for a few seconds. */
    public static final double FRICTION = 0.00001;
    /** Name of the plectrum (the haptic avatar). */
    public static final String PLECTRUM = "plectrum";
    /** Smoothing of the plectrum: the EWMA length, in steps, that upsamples the 1 kHz device position. */
    public static final int SMOOTHING = 40;
    /** Sphere of action of the plectrum: the contact distance, model units. */
    public static final double SPHERE = 0.08;
    /** Stiffness of the plectrum's contact with each mass, per step squared. */
    public static final double CONTACT_STIFFNESS = 0.01;
    /** Damping of the plectrum's contact with each mass, per step. */
    public static final double CONTACT_DAMPING = 0.001;
    /** The mass the sound is taken from (its y displacement); near an end, so that every mode is heard. */
    public static final int LISTENED_MASS = 3;

    private PluckScene() {
    }

    /** @return the name of mass {@code i}: "m1" to "m30" on the string, "g0" and "g31" for the fixed ends. */
    public static String mass(int i) {
        return i == 0 || i == MASSES + 1 ? "g" + i : "m" + i;
    }

    /** @return the length of the string between its fixed ends, model units. */
    public static double length() {
        return (MASSES + 1) * SPACING;
    }

    /**
     * Builds the scene: the straight string at rest along x from (0, 0) to ({@link #length()}, 0), and the
     * plectrum at {@code plectrum}.
     *
     * @param plectrum where the plectrum starts, model units
     * @return the initialised model, at {@value #AUDIO_RATE} steps per second
     */
    public static PhysicalModel build(Vect3D plectrum) {
        PhysicalModel mdl = new PhysicalModel(AUDIO_RATE, 60, paramSystem.ALGO_UNITS);
        mdl.setGravity(0);
        mdl.setFriction(FRICTION);
        mdl.addGround3D(mass(0), new Vect3D(0, 0, 0));
        for (int i = 1; i <= MASSES; i++) {
            mdl.addMass2DPlane(mass(i), MASS, new Vect3D(i * SPACING, 0, 0), new Vect3D());
        }
        mdl.addGround3D(mass(MASSES + 1), new Vect3D(length(), 0, 0));
        for (int i = 0; i <= MASSES; i++) {
            mdl.addSpringDamper3D("s" + i, REST, STIFFNESS, DAMPING, mass(i), mass(i + 1));
        }
        mdl.addHapticInput3D(PLECTRUM, plectrum, SMOOTHING);
        for (int i = 1; i <= MASSES; i++) {
            mdl.addContact3D("pick" + i, SPHERE, CONTACT_STIFFNESS, CONTACT_DAMPING, PLECTRUM, mass(i));
        }
        mdl.init();
        return mdl;
    }

    /** @return the transverse stiffness of one stretched link, {@code K (1 - l0 / d)}, per step squared. */
    public static double transverseStiffness() {
        return STIFFNESS * (1 - REST / SPACING);
    }

    /**
     * The frequency of transverse mode {@code m} of the string in the explicit scheme (small motion, no
     * damping): {@code cos w_m = 1 - 2 (kt / M) sin^2(m pi / (2 (N + 1)))}, {@code f = w fs / (2 pi)}.
     *
     * @param m the mode, 1 for the fundamental
     * @return its frequency in Hz at {@value #AUDIO_RATE} steps per second
     */
    public static double modeHz(int m) {
        double s = Math.sin(m * Math.PI / (2.0 * (MASSES + 1)));
        double cosW = 1 - 2 * (transverseStiffness() / MASS) * s * s;
        return Math.acos(cosW) * AUDIO_RATE / (2 * Math.PI);
    }
}
