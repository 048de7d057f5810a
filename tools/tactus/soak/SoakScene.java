package tactus.soak;

import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * The soaked model: a string of {@value #MASSES} {@code Mass2DPlane} beads between two grounds (ALGO_UNITS,
 * 44.1 kHz, a stable spring-damper chain), a plectrum ({@code HapticInput3D}) with a contact to every bead, a link
 * subset {@value #STRINGS} with a stiffness ramp controller {@value #RAMP}, and a mass subset {@value #BEADS}
 * with a contact group. Names: grounds g0 and g{MASSES+1}, beads m1..mN, springs s0..sN, contacts pick1..pickN.
 */
final class SoakScene {
    static final int RATE = 44100;
    static final int MASSES = 16;
    static final double SPACING = 0.1;
    static final double REST = 0.05;
    static final double STIFFNESS = 0.2;
    static final double DAMPING = 0.0001;
    static final String PLECTRUM = "plectrum";
    static final int SMOOTHING = 40;
    static final double SPHERE = 0.08;
    static final double CONTACT_K = 0.01;
    static final double CONTACT_Z = 0.001;
    static final String STRINGS = "strings";
    static final String BEADS = "beads";
    static final String RAMP = "ramp";
    static final float RAMP_SECONDS = 0.2f;
    /** The bead the PhyUGen listens to. */
    static final int LISTENED = 3;

    private SoakScene() {
    }

    static String mass(int i) {
        return i == 0 || i == MASSES + 1 ? "g" + i : "m" + i;
    }

    static String spring(int i) {
        return "s" + i;
    }

    static String pick(int i) {
        return "pick" + i;
    }

    static double length() {
        return (MASSES + 1) * SPACING;
    }

    /** A new model with the scene, initialised. */
    static PhysicalModel create() {
        PhysicalModel m = new PhysicalModel(RATE, 60, paramSystem.ALGO_UNITS);
        populate(m, new Vect3D(length() / 2, 0.4, 0));
        m.init();
        return m;
    }

    /** How the scene's calls are made: directly, or each timed as one API call (the chaos thread's rebuild). */
    interface Api {
        /** Makes one API call. */
        void call(String what, Runnable call);
    }

    /** Calls made directly. */
    static final Api DIRECT = (what, call) -> call.run();

    /** Adds the scene to an empty model (after {@code clearModel()}); the caller calls {@code init()}. */
    static void populate(PhysicalModel m, Vect3D plectrum) {
        populate(m, plectrum, DIRECT);
    }

    /** As {@link #populate(PhysicalModel, Vect3D)}, each call made through {@code api}. */
    static void populate(PhysicalModel m, Vect3D plectrum, Api api) {
        api.call("setGravity", () -> m.setGravity(0));
        api.call("setFriction", () -> m.setFriction(0.00001));
        api.call("addGround3D", () -> m.addGround3D(mass(0), new Vect3D(0, 0, 0)));
        for (int i = 1; i <= MASSES; i++) {
            int n = i;
            api.call("addMass2DPlane", () -> m.addMass2DPlane(mass(n), 1.0, new Vect3D(n * SPACING, 0, 0), new Vect3D()));
        }
        api.call("addGround3D", () -> m.addGround3D(mass(MASSES + 1), new Vect3D(length(), 0, 0)));
        for (int i = 0; i <= MASSES; i++) {
            int n = i;
            api.call("addSpringDamper3D", () -> m.addSpringDamper3D(spring(n), REST, STIFFNESS, DAMPING, mass(n),
                    mass(n + 1)));
        }
        api.call("addHapticInput3D", () -> m.addHapticInput3D(PLECTRUM, plectrum, SMOOTHING));
        for (int i = 1; i <= MASSES; i++) {
            int n = i;
            api.call("addContact3D", () -> m.addContact3D(pick(n), SPHERE, CONTACT_K, CONTACT_Z, PLECTRUM, mass(n)));
        }
        api.call("createLinkSubset", () -> m.createLinkSubset(STRINGS));
        for (int i = 0; i <= MASSES; i++) {
            int n = i;
            api.call("addLinkToSubset", () -> m.addLinkToSubset(spring(n), STRINGS));
        }
        api.call("createMatSubset", () -> m.createMatSubset(BEADS));
        for (int i = 1; i <= MASSES; i++) {
            int n = i;
            api.call("addMatToSubset", () -> m.addMatToSubset(mass(n), BEADS));
        }
        api.call("addContactGroup", () -> m.addContactGroup(BEADS, SPACING / 4, 0.05, 0.001));
        api.call("addParamController", () -> m.addParamController(RAMP, STRINGS, "stiffness", RAMP_SECONDS));
    }

    /** Device-to-model mapping for the haptic loop: position gain (model units per metre). */
    static final double ALPHA = 25;
    /** Force gain (newtons per model force unit). */
    static final double BETA = 1500;
    /** Where the handle's path is centred, device metres. */
    static final double CENTRE_X = 0.01;
    static final double CENTRE_Y = 0.08;

    /** The hand's path in device metres: a slow Lissajous figure that crosses the string now and then. */
    static void handAt(double t, double[] out) {
        out[0] = CENTRE_X + 0.02 * Math.cos(2 * Math.PI * 0.5 * t);
        out[1] = CENTRE_Y + 0.015 * Math.sin(2 * Math.PI * 0.7 * t);
    }

    static double originX() {
        return length() / 2 + ALPHA * CENTRE_X;
    }

    static double originY() {
        return -ALPHA * CENTRE_Y;
    }
}
