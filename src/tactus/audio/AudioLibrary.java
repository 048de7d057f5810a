package tactus.audio;

import tactus.PhysicalModel;
import tactus.internal.model.OptionalLibrary;

/**
 * Makes a {@link PhyUGen} after checking that Minim is on the class path, so that a program run without Minim is
 * told to add it instead of failing with {@code NoClassDefFoundError: ddf/minim/UGen}.
 *
 * <p>This class touches no Minim type until the check has passed. {@code new PhyUGen(model)} cannot check this
 * itself: the JVM loads Minim's {@code UGen}, the superclass, before any of PhyUGen's code runs.
 */
public final class AudioLibrary {
    private AudioLibrary() {
    }

    /** Whether Minim is on the class path (checked once per JVM). */
    public static boolean isMinimPresent() {
        return OptionalLibrary.MINIM.isPresent();
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
        OptionalLibrary.MINIM.require(call, "add Minim to the class path (in a sketch: Sketch > Import Library > "
                + "Minim; with Gradle: implementation 'net.compartmental.code:minim:2.2.2'), or step the model "
                + "without sound with computeStep()");
    }
}
