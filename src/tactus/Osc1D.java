package tactus;

/** An oscillator that moves along z only. */
public final class Osc1D extends Oscillator {
    Osc1D(PhysicalModel model, int id) {
        super(model, id);
    }
}
