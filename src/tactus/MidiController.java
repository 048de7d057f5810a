package tactus;

/**
 * Maps a MIDI control change (values 0 to 127) onto one parameter of a subset, through a
 * {@link ParamController} that ramps to each new value. Tactus does not depend on any MIDI library: with The
 * MidiBus installed, the sketch forwards its callback, for example
 * {@code void controllerChange(int channel, int number, int value) { for (MidiController mc : ctrls)
 * mc.changeParam(number, value); }}. Controllers of the same subset and parameter share one ramp.
 */
public class MidiController extends AbstractController {
    private final int ctrl;
    private final ParamController ramp;

    /**
     * Creates a controller and sets the parameter to the middle of its range at once.
     *
     * @param ctrl the MIDI control-change number, 0 to 127
     * @param min the parameter value for MIDI value 0
     * @param max the parameter value for MIDI value 127
     * @param rampTime the ramp duration in seconds
     */
    public MidiController(PhysicalModel pm, int ctrl, float min, float max, String subsetName, String param,
                          float rampTime) {
        super(pm, subsetName, param);
        if (ctrl < 0 || ctrl > 127) {
            throw new IllegalArgumentException("MidiController(\"" + subsetName + "\"): ctrl must be 0..127, got "
                    + ctrl);
        }
        this.ctrl = ctrl;
        setParam("vmin", 0);
        setParam("vmax", 127);
        setParam("min", min);
        setParam("max", max);
        String key = subsetName + "_" + param;
        pm.addParamController(key, subsetName, param, rampTime);
        ramp = pm.getParamController(key);
        ramp.init((min + max) / 2);
    }

    /** Creates a controller with the given ramp time (see the constructor). */
    public static MidiController addMidiController(PhysicalModel pm, int ctrl, float min, float max,
                                                   String subsetName, String param, float rampTime) {
        return new MidiController(pm, ctrl, min, max, subsetName, param, rampTime);
    }

    /** Creates a controller whose ramp lasts one simulation step. */
    public static MidiController addMidiController(PhysicalModel pm, int ctrl, float min, float max,
                                                   String subsetName, String param) {
        return new MidiController(pm, ctrl, min, max, subsetName, param, 1f / pm.getSimRate());
    }

    /** {@return the MIDI control-change number this controller listens to} */
    public int getControlNumber() {
        return ctrl;
    }

    /** Handles a control change: does nothing unless {@code ctrl} is this controller's number. */
    public void changeParam(int ctrl, int value) {
        if (ctrl == this.ctrl) {
            changeParam(value);
        }
    }

    /** Ramps the parameter to the value that MIDI value {@code value} (0 to 127) maps to. */
    public void changeParam(int value) {
        ramp.triggerRamp(linearScale(Math.max(0, Math.min(127, value))));
    }
}
