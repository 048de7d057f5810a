package tactus.haptics;

/**
 * The Haply board a {@link Board} talks to: how many motor/encoder ports it has, its PWM resolution, and
 * which analog pins its firmware actually handles.
 */
public enum BoardModel {
    /**
     * Haply M0 (firmware V0.3): ports 1-2, 10-bit motor PWM, analog pins A0-A4 (only A1 and A2 are read; A5
     * would overrun the firmware's 5-slot table, A6 and up are dropped).
     */
    M0(2, 1023, 4, false),
    /** Haply M3 (firmware V1.5): ports 1-4, 12-bit motor PWM, analog pins A0-A11. */
    M3(4, 4095, 11, false),
    /** Haply Modular Development Kit (firmware V0.4): ports 1-4, 12-bit PWM; the firmware inverts motor ports 2 and 4. */
    DEV_KIT(4, 4095, 11, true);

    private final int ports;
    private final int pwmResolution;
    private final int maxAnalogPin;
    private final boolean invertsEvenMotorPorts;

    BoardModel(int ports, int pwmResolution, int maxAnalogPin, boolean invertsEvenMotorPorts) {
        this.ports = ports;
        this.pwmResolution = pwmResolution;
        this.maxAnalogPin = maxAnalogPin;
        this.invertsEvenMotorPorts = invertsEvenMotorPorts;
    }

    /** Number of motor/encoder ports (numbered 1..ports). */
    public int ports() {
        return ports;
    }

    /** Full-scale motor PWM duty (1023 or 4095). */
    public int pwmResolution() {
        return pwmResolution;
    }

    /** Highest analog pin n ("An") the firmware handles. */
    public int maxAnalogPin() {
        return maxAnalogPin;
    }

    /** True if the firmware inverts the rotation of motor ports 2 and 4. */
    public boolean invertsEvenMotorPorts() {
        return invertsEvenMotorPorts;
    }

    /** The firmware's torque limit in N m: |tau| is clipped to this before conversion to PWM. */
    public static final double MAX_TORQUE = 0.123;
}
