package tactus;


/** An oscillator that moves along z only. */
public final class Osc1D extends Oscillator {
    Osc1D(ModuleHandles handles, int id, int stamp) {
        super(handles, id, stamp);
    }
}
