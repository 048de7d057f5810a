package tactus.audio;

import javax.sound.sampled.Control;
import javax.sound.sampled.Line;
import javax.sound.sampled.LineListener;

/**
 * The parts of a Java Sound {@link Line} that Tactus's virtual output does not have: no controls (gain, pan,
 * ...) and no line events. Shared by the virtual mixer and its line.
 */
abstract class BareLine implements Line {

    @Override
    public Control[] getControls() {
        return new Control[0];
    }

    @Override
    public boolean isControlSupported(Control.Type control) {
        return false;
    }

    @Override
    public Control getControl(Control.Type control) {
        throw new IllegalArgumentException("Tactus virtual output: no control " + control);
    }

    @Override
    public void addLineListener(LineListener listener) {
    }

    @Override
    public void removeLineListener(LineListener listener) {
    }
}
