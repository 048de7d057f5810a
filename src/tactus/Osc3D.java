package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A 3D oscillator: a mass tied to its initial position by an internal spring and damper. */
public final class Osc3D extends Oscillator {
    Osc3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
