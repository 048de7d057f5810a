package tactus.haptics;

import tactus.haptics.pantograph.PantographKinematics;

/**
 * Known Haply pantograph hardware: link lengths, motor and encoder wiring, encoder calibration, and the
 * mechanism the original sketches used. Every value can still be set by hand on {@link Device} and
 * {@link PantographKinematics}; these are the calibrations published with the hardware's sketches.
 */
public enum HaplyPreset {
    /**
     * 2017-18 Haply development kit, M0 and M3 boards (hAPI's Hello_Wall): l, L, d = 0.05, 0.07, 0.02 m;
     * actuators (1, CW, port 1), (2, CW, port 2); encoders (1, CW, 180 deg, 13824, port 1), (2, CW, 0 deg,
     * 13824, port 2); torque gain 0.1 / l as in hAPI's 2018 Pantograph.
     */
    HAPLY_2018(0.05, 0.07, 0.02, true,
            new int[] {0, 0}, new int[] {1, 2},
            new int[] {0, 0}, new float[] {180f, 0f}, new float[] {13824f, 13824f}, new int[] {1, 2}),
    /**
     * 2DIY hardware version 2: l, L, d = 0.07, 0.09, 0 m; actuators (1, CCW, port 2), (2, CW, port 1);
     * encoders (1, CCW, 241 deg, 10752, port 2), (2, CW, -61 deg, 10752, port 1); torque gain 1.
     */
    TWO_DIY_V2(0.07, 0.09, 0.0, false,
            new int[] {1, 0}, new int[] {2, 1},
            new int[] {1, 0}, new float[] {241f, -61f}, new float[] {10752f, 10752f}, new int[] {2, 1}),
    /**
     * 2DIY hardware version 3 (maze_study_demo, 2021): l, L, d = 0.07, 0.09, 0.038 m; actuators (1, CCW,
     * port 2), (2, CCW, port 1); encoders (1, CCW, 168 deg, 4880, port 2), (2, CCW, 12 deg, 4880, port 1);
     * torque gain 1.
     */
    TWO_DIY_V3(0.07, 0.09, 0.038, false,
            new int[] {1, 1}, new int[] {2, 1},
            new int[] {1, 1}, new float[] {168f, 12f}, new float[] {4880f, 4880f}, new int[] {2, 1});

    private final double l;
    private final double bigL;
    private final double d;
    private final boolean legacyGain;
    private final int[] motorRotation;
    private final int[] motorPort;
    private final int[] encoderRotation;
    private final float[] encoderOffset;
    private final float[] encoderResolution;
    private final int[] encoderPort;

    HaplyPreset(double l, double bigL, double d, boolean legacyGain, int[] motorRotation, int[] motorPort,
                int[] encoderRotation, float[] encoderOffset, float[] encoderResolution, int[] encoderPort) {
        this.l = l;
        this.bigL = bigL;
        this.d = d;
        this.legacyGain = legacyGain;
        this.motorRotation = motorRotation;
        this.motorPort = motorPort;
        this.encoderRotation = encoderRotation;
        this.encoderOffset = encoderOffset;
        this.encoderResolution = encoderResolution;
        this.encoderPort = encoderPort;
    }

    /** Proximal link length l in metres. */
    public double l() {
        return l;
    }

    /** Distal link length L in metres. */
    public double bigL() {
        return bigL;
    }

    /** Motor spacing d in metres. */
    public double d() {
        return d;
    }

    /** The torque gain of the original sketches' mechanism (0.1 / l for 2018, 1 for 2021). */
    public double gain() {
        return legacyGain ? 0.1 / l : 1.0;
    }

    /** The board port (1..2) of joint j's motor (j = 1 for theta1, 2 for theta2). */
    public int motorPort(int joint) {
        return motorPort[joint - 1];
    }

    /** The rotation byte (0 = CW, 1 = CCW) of joint j's motor. */
    public int motorRotation(int joint) {
        return motorRotation[joint - 1];
    }

    /** The board port of joint j's encoder. */
    public int encoderPort(int joint) {
        return encoderPort[joint - 1];
    }

    /** The rotation byte of joint j's encoder. */
    public int encoderRotation(int joint) {
        return encoderRotation[joint - 1];
    }

    /** The angle in degrees joint j's encoder reports at the calibration pose. */
    public float encoderOffset(int joint) {
        return encoderOffset[joint - 1];
    }

    /** The resolution sent for joint j's encoder. */
    public float encoderResolution(int joint) {
        return encoderResolution[joint - 1];
    }

    /** A new mechanism with this hardware's geometry and gain (hAPI's Pantograph() for HAPLY_2018). */
    public Pantograph newMechanism() {
        if (legacyGain) {
            return new Pantograph();
        }
        return new Pantograph(this == TWO_DIY_V2 ? 2 : 3);
    }

    /** New kinematics with this hardware's l, L, d. */
    public PantographKinematics newKinematics() {
        return new PantographKinematics(l, bigL, d);
    }

    /**
     * Configures a device as the original sketches did: mechanism, actuators 1-2 and encoders 1-2. The setup
     * is not sent; call {@link Device#device_set_parameters()} with the handle in the calibration pose.
     */
    public void configure(Device device) {
        device.set_mechanism(newMechanism());
        for (int j = 1; j <= 2; j++) {
            device.add_actuator(j, motorRotation(j), motorPort(j));
        }
        for (int j = 1; j <= 2; j++) {
            device.add_encoder(j, encoderRotation(j), encoderOffset(j), encoderResolution(j), encoderPort(j));
        }
    }
}
