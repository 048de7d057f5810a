package tactus.audio;

import tactus.PhysicalModel;

/**
 * Makes a {@link PhyUGen} after checking that Minim is on the class path, so that a program run without Minim is
 * told to add it instead of failing with {@code NoClassDefFoundError: ddf/minim/UGen}.
 *
 * <p>This class touches no Minim type until the check has passed. {@code new PhyUGen(model)} cannot check this
 * itself: the JVM loads Minim's {@code UGen}, the superclass, before any of PhyUGen's code runs.
 */
public final class AudioLibrary {
    private static final String PROBE = "ddf.minim.UGen";
    /** 0 = not checked yet, 1 = present, -1 = absent (a race checks twice, harmlessly). */
    private static volatile int minimState;

    private AudioLibrary() {
    }

    /** Whether Minim is on the class path (checked once per JVM). */
    public static boolean isMinimPresent() {
        int s = minimState;
        if (s == 0) {
            s = probe() ? 1 : -1;
            minimState = s;
        }
        return s > 0;
    }

    /**
     * Makes a PhyUGen that steps the model at the audio rate: the same as {@code new PhyUGen(model)}, after the
     * check.
     *
     * @throws IllegalStateException naming Minim and how to add it, when Minim is not on the class path
     */
    public static PhyUGen newPhyUGen(PhysicalModel model) {
        requireMinim("new PhyUGen(model)");
        return new PhyUGen(model);
    }

    /**
     * Throws when Minim is not on the class path.
     *
     * @param call what needs Minim, as the message shows it
     * @throws IllegalStateException naming Minim, how to add it, and how to step a model without sound
     */
    public static void requireMinim(String call) {
        if (!isMinimPresent()) {
            throw new IllegalStateException("Tactus: " + call + " needs Minim (the Processing library, or "
                    + "net.compartmental.code:minim:2.2.2 from Maven), which is not on the class path (" + PROBE
                    + " was not found); add Minim to the class path (in a sketch: Sketch > Import Library > Minim; "
                    + "with Gradle: implementation 'net.compartmental.code:minim:2.2.2'), or step the model without "
                    + "sound with computeStep()");
        }
    }

    /** Loads Minim's UGen by name without initialising it; false when it cannot be found. */
    private static boolean probe() {
        try {
            Class.forName(PROBE, false, AudioLibrary.class.getClassLoader());
            return true;
        } catch (ClassNotFoundException | LinkageError e) {
            return false;
        }
    }
}
