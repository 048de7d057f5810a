package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** An oscillator that moves along z only. */
public final class Osc1D extends Oscillator {
    Osc1D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
