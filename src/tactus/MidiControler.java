package tactus;

/**
 * The spelling of {@link MidiController} used by the paper-era example sketches
 * ({@code MidiControler.addMidiControler(...)}); it behaves exactly like {@link MidiController}.
 */
public class MidiControler extends MidiController {
    /** Creates a controller (see {@link MidiController#MidiController}). */
    public MidiControler(PhysicalModel pm, int ctrl, float min, float max, String subsetName, String param,
                         float rampTime) {
        super(pm, ctrl, min, max, subsetName, param, rampTime);
    }

    /** Creates a controller with the given ramp time. */
    public static MidiControler addMidiControler(PhysicalModel pm, int ctrl, float min, float max,
                                                 String subsetName, String param, float rampTime) {
        return new MidiControler(pm, ctrl, min, max, subsetName, param, rampTime);
    }

    /** Creates a controller whose ramp lasts one simulation step. */
    public static MidiControler addMidiControler(PhysicalModel pm, int ctrl, float min, float max,
                                                 String subsetName, String param) {
        return new MidiControler(pm, ctrl, min, max, subsetName, param, 1f / pm.getSimRate());
    }
}
