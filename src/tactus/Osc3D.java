package tactus;


/** A 3D oscillator: a mass tied to its initial position by an internal spring and damper. */
public final class Osc3D extends Oscillator {
    Osc3D(ModuleHandles handles, int id, int stamp) {
        super(handles, id, stamp);
    }
}
