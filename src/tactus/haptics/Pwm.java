package tactus.haptics;

/** A PWM output pin of a {@link Device}: pin number (0..13) and pulse width as a byte value 0..255. */
public class Pwm {
    private int pin;
    private int value;

    /** Creates an unassigned PWM pin. */
    public Pwm() {
    }

    /** Creates a PWM pin with a pulse width in percent (clipped to 0..100). */
    public Pwm(int pin, float pulseWidthPercent) {
        this.pin = pin;
        set_pulse(pulseWidthPercent);
    }

    /** Sets the pin number. */
    public void set_pin(int pin) {
        this.pin = pin;
    }

    /** Sets the pulse width in percent; stored as trunc(percent * 255 / 100) clipped to 0..255. */
    public void set_pulse(float percent) {
        if (Float.isNaN(percent)) {
            throw new IllegalArgumentException("Pwm.set_pulse(pin " + pin + "): percent must be a number, got NaN");
        }
        int v = (int) (percent * 255f / 100f);
        value = Math.max(0, Math.min(255, v));
    }

    /** The pin number. */
    public int get_pin() {
        return pin;
    }

    /** The pulse width as the byte value sent to the board (0..255). */
    public int get_value() {
        return value;
    }

    /** The pulse width in percent (value * 100 / 255, exact, unlike hAPI's integer division). */
    public float get_pulse() {
        return value * 100f / 255f;
    }
}
