package tactus.haptics;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import tactus.haptics.transport.WireFormat;

/**
 * One mechanism on a Haply board (hAPI 2.x compatible): its motors, encoders, analog inputs and PWM pins,
 * and the messages that configure, poll and drive it.
 *
 * <p>Every configuration call is checked before anything is sent: device id 0 (the firmware's "unassigned"
 * marker), ports the board does not have, indices out of 1..4, rotations other than 0/1, zero or non-finite
 * resolutions, unknown analog pins and duplicate ports are refused with an exception naming the value.
 * The setup is sent once: a second {@link #device_set_parameters()} would re-home the encoders at the current
 * pose, so it is refused, as is changing the configuration after it, and so is the setup of a second device on
 * the same board (the firmware's setup clears every assignment). Non-finite torques are sent as 0, and torques
 * above the firmware's 0.123 N m clip are scaled down together so that the force keeps its direction (the
 * firmware would clip each motor alone).
 */
public class Device {
    /** Highest actuator or encoder index (hAPI numbers them 1..4). */
    public static final int MAX_INDEX = 4;
    /** Highest PWM pin number the firmware accepts. */
    public static final int MAX_PWM_PIN = 13;

    private final byte id;
    private final Board board;
    private final int ports;
    private Mechanisms mechanism;

    private final Actuator[] actuators = new Actuator[MAX_INDEX];  // by index - 1
    private final Sensor[] encoders = new Sensor[MAX_INDEX];       // by index - 1
    private final int[] actuatorAtPort;                            // index or 0, by port - 1
    private final int[] encoderAtPort;                             // index or 0, by port - 1
    private final List<Sensor> analogs = new ArrayList<>();
    private final List<Pwm> pwms = new ArrayList<>();

    private boolean configured;
    private int nMotors;
    private int nEncoders;
    private int nSensors;
    private int nPwm;
    private byte[] writeBuffer;
    private float[] torquesByPort;
    private int[] pwmValues;
    private float[] frame;
    private long nonFiniteTorques;
    private long scaledWrites;
    private byte[] zeroMessage;

    /** Creates a device with an id (1..255 as an unsigned byte; 0 is refused) on a board. */
    public Device(byte deviceID, Board board) {
        if (deviceID == 0) {
            throw new IllegalArgumentException("Device: device id 0 is the firmware's 'unassigned' marker "
                    + "and would claim every free pin; use an id from 1 to 255, got 0");
        }
        if (board == null) {
            throw new IllegalArgumentException("Device(id " + (deviceID & 0xFF) + "): board must not be null");
        }
        this.id = deviceID;
        this.board = board;
        this.ports = board.model().ports();
        this.actuatorAtPort = new int[ports];
        this.encoderAtPort = new int[ports];
    }

    /** The device id. */
    public byte id() {
        return id;
    }

    /** The board this device is on. */
    public Board board() {
        return board;
    }

    /** Sets the mechanism that maps angles to positions and forces to torques. */
    public void set_mechanism(Mechanisms mechanism) {
        if (mechanism == null) {
            throw new IllegalArgumentException(what() + ".set_mechanism: mechanism must not be null");
        }
        this.mechanism = mechanism;
    }

    /** The mechanism, or null if none was set. */
    public Mechanisms mechanism() {
        return mechanism;
    }

    /** Adds motor number actuator (1..4) with a rotation (0 = CW, 1 = CCW) on a board port. */
    public void add_actuator(int actuator, int rotation, int port) {
        String op = what() + ".add_actuator";
        requireUnconfigured(op);
        checkIndex(op, "actuator", actuator);
        checkRotation(op, rotation);
        checkPort(op, port);
        int other = actuatorAtPort[port - 1];
        if (other != 0 && other != actuator) {
            throw new IllegalArgumentException(op + ": port " + port + " already drives actuator " + other);
        }
        Actuator old = actuators[actuator - 1];
        if (old != null) {
            actuatorAtPort[old.get_port() - 1] = 0;
        }
        actuators[actuator - 1] = new Actuator(actuator, rotation, port);
        actuatorAtPort[port - 1] = actuator;
    }

    /**
     * Adds encoder number encoder (1..4) with a rotation (0/1), the angle in degrees it reports at the
     * calibration pose, its resolution (counts per turn, as the board expects it; > 0), on a board port.
     */
    public void add_encoder(int encoder, int rotation, float offset, float resolution, int port) {
        String op = what() + ".add_encoder";
        requireUnconfigured(op);
        checkIndex(op, "encoder", encoder);
        checkRotation(op, rotation);
        checkPort(op, port);
        if (!Float.isFinite(offset)) {
            throw new IllegalArgumentException(op + "(encoder " + encoder + "): offset must be a finite angle in degrees, got " + offset);
        }
        if (!(resolution > 0) || !Float.isFinite(resolution)) {
            throw new IllegalArgumentException(op + "(encoder " + encoder + "): resolution must be a finite count > 0, got " + resolution);
        }
        int other = encoderAtPort[port - 1];
        if (other != 0 && other != encoder) {
            throw new IllegalArgumentException(op + ": port " + port + " already reads encoder " + other);
        }
        Sensor old = encoders[encoder - 1];
        if (old != null) {
            encoderAtPort[old.get_port() - 1] = 0;
        }
        encoders[encoder - 1] = new Sensor(encoder, rotation, offset, resolution, port);
        encoderAtPort[port - 1] = encoder;
    }

    /** Adds an analog input by pin name "A0".."An" (the highest n depends on the board model). */
    public void add_analog_sensor(String pin) {
        String op = what() + ".add_analog_sensor";
        requireUnconfigured(op);
        int n = -1;
        if (pin != null && pin.length() >= 2 && (pin.charAt(0) == 'A' || pin.charAt(0) == 'a')) {
            try {
                n = Integer.parseInt(pin.substring(1));
            } catch (NumberFormatException e) {
                n = -1;
            }
        }
        int max = board.model().maxAnalogPin();
        if (n < 0 || n > max) {
            throw new IllegalArgumentException(op + ": pin must be \"A0\"..\"A" + max + "\" on a " + board.model()
                    + " board, got " + (pin == null ? "null" : "\"" + pin + "\""));
        }
        for (Sensor s : analogs) {
            if (s.get_port() == WireFormat.ANALOG_PIN_BASE + n) {
                throw new IllegalArgumentException(op + ": pin \"" + pin + "\" was already added");
            }
        }
        Sensor s = new Sensor();
        s.set_encoder(analogs.size() + 1);
        s.set_port(WireFormat.ANALOG_PIN_BASE + n);
        analogs.add(s);
    }

    /** Adds a PWM output pin (0..13). */
    public void add_pwm_pin(int pin) {
        String op = what() + ".add_pwm_pin";
        requireUnconfigured(op);
        if (pin < 0 || pin > MAX_PWM_PIN) {
            throw new IllegalArgumentException(op + ": pin must be 0.." + MAX_PWM_PIN + ", got " + pin);
        }
        for (Pwm p : pwms) {
            if (p.get_pin() == pin) {
                throw new IllegalArgumentException(op + ": pin " + pin + " was already added");
            }
        }
        pwms.add(new Pwm(pin, 0));
        pwms.sort((a, b) -> Integer.compare(a.get_pin(), b.get_pin()));
    }

    /** Sets the pulse width of a PWM pin in percent (0..100, clipped); sent with the next write. */
    public void set_pwm_pulse(int pin, float percent) {
        pwmAt(what() + ".set_pwm_pulse", pin).set_pulse(percent);
    }

    /** The pulse width of a PWM pin in percent. */
    public float get_pwm_pulse(int pin) {
        return pwmAt(what() + ".get_pwm_pulse", pin).get_pulse();
    }

    /**
     * Sends the setup message. The board presets each encoder to its offset at the current pose, so the
     * handle must be in the calibration pose. Sent once per session: a second call is refused.
     */
    public void device_set_parameters() {
        String op = what() + ".device_set_parameters";
        if (configured) {
            throw new IllegalStateException(op + ": the setup was already sent; sending it again mid-session "
                    + "would re-home the encoders at the current pose");
        }
        board.checkNoOtherSetup(this, op);
        checkFirmwareDirectionSlots(op);
        int[] motorDirs = new int[ports];
        int[] encDirs = new int[ports];
        float[] offsets = new float[ports];
        float[] resolutions = new float[ports];
        nMotors = 0;
        nEncoders = 0;
        for (int p = 0; p < ports; p++) {
            Actuator a = actuatorAtPort[p] == 0 ? null : actuators[actuatorAtPort[p] - 1];
            motorDirs[p] = a == null ? -1 : a.get_direction();
            if (a != null) {
                nMotors++;
            }
            Sensor e = encoderAtPort[p] == 0 ? null : encoders[encoderAtPort[p] - 1];
            encDirs[p] = e == null ? -1 : e.get_direction();
            if (e != null) {
                offsets[p] = e.get_offset();
                resolutions[p] = e.get_resolution();
                nEncoders++;
            }
        }
        int[] sensorPins = new int[analogs.size()];
        for (int i = 0; i < sensorPins.length; i++) {
            sensorPins[i] = analogs.get(i).get_port();
        }
        int[] pwmPins = new int[pwms.size()];
        for (int i = 0; i < pwmPins.length; i++) {
            pwmPins[i] = pwms.get(i).get_pin();
        }
        nSensors = sensorPins.length;
        nPwm = pwmPins.length;
        writeBuffer = new byte[WireFormat.writeLength(nPwm, nMotors)];
        torquesByPort = new float[nMotors];
        pwmValues = new int[nPwm];
        frame = new float[nSensors + nEncoders];
        zeroMessage = new byte[writeBuffer.length];
        WireFormat.encodeWrite(id, new int[nPwm], nPwm, new float[nMotors], nMotors, zeroMessage);
        byte[] setup = WireFormat.setup(id, motorDirs, encDirs, offsets, resolutions, sensorPins, pwmPins);
        board.send(setup, setup.length);
        configured = true;
        board.register(this);
    }

    /** True once the setup has been sent. */
    public boolean isConfigured() {
        return configured;
    }

    /**
     * Reads the newest reply from the board: analog values first, then encoder angles in port order. On a
     * timeout or a bad frame the previous values are kept (see the board's counters).
     */
    public void device_read_data() {
        requireConfigured("device_read_data");
        if (board.readFrame(id, frame.length, frame)) {
            takeFrame();
        }
    }

    private void takeFrame() {
        int k = 0;
        for (int i = 0; i < analogs.size(); i++) {
            analogs.get(i).set_value(frame[k++]);
        }
        for (int p = 0; p < ports; p++) {
            if (encoderAtPort[p] != 0) {
                encoders[encoderAtPort[p] - 1].set_value(frame[k++]);
            }
        }
    }

    /**
     * Takes the newest reply if a complete one has arrived, without waiting (unlike hAPI's
     * {@link #device_read_data()}). Returns true if new values were read.
     */
    public boolean poll_data() {
        requireConfigured("poll_data");
        if (!board.pollFrame(id, frame.length, frame)) {
            return false;
        }
        takeFrame();
        return true;
    }

    /** Asks for a reply without force: sends zero torques and the current PWM values. */
    public void device_read_request() {
        requireConfigured("device_read_request");
        Arrays.fill(torquesByPort, 0f);
        sendWrite();
    }

    /** Sends the stored torques (in port order) and PWM values; the board answers with one reply. */
    public void device_write_torques() {
        requireConfigured("device_write_torques");
        int k = 0;
        for (int p = 0; p < ports; p++) {
            if (actuatorAtPort[p] != 0) {
                float t = actuators[actuatorAtPort[p] - 1].get_torque();
                if (!Float.isFinite(t)) {
                    t = 0f;
                    nonFiniteTorques++;
                }
                torquesByPort[k++] = t;
            }
        }
        keepDirectionWithinTheClip();
        float ramp = board.torqueRamp();   // below 1 only just after the motor guard zeroed a paused JVM's motors
        if (ramp < 1f) {
            for (int i = 0; i < nMotors; i++) {
                torquesByPort[i] *= ramp;
            }
        }
        sendWrite();
    }

    /**
     * The firmware clips each motor's |torque| to 0.123 N m on its own, which turns the force (by up to 34
     * degrees on a pantograph); instead, when any torque is above the clip, scale all of them by the same
     * factor so that the largest is exactly at the clip and the direction holds.
     */
    private void keepDirectionWithinTheClip() {
        float max = 0f;
        for (int i = 0; i < nMotors; i++) {
            max = Math.max(max, Math.abs(torquesByPort[i]));
        }
        float clip = (float) BoardModel.MAX_TORQUE;
        if (max > clip) {
            float k = clip / max;
            for (int i = 0; i < nMotors; i++) {
                torquesByPort[i] *= k;
            }
            scaledWrites++;
        }
    }

    /** Number of torque writes scaled down together because a torque was above the firmware's 0.123 N m clip. */
    public long scaledWrites() {
        return scaledWrites;
    }

    /** Number of non-finite torques replaced by 0 before sending. */
    public long nonFiniteTorques() {
        return nonFiniteTorques;
    }

    /** The encoder angles in degrees, in encoder-index order (a new array). */
    public float[] get_device_angles() {
        int n = 0;
        for (Sensor e : encoders) {
            if (e != null) {
                n++;
            }
        }
        float[] out = new float[n];
        int k = 0;
        for (Sensor e : encoders) {
            if (e != null) {
                out[k++] = e.get_value();
            }
        }
        return out;
    }

    /**
     * The resolution of the encoder with this index (1 or 2 on a 2DIY), in counts per turn as given to
     * {@link #add_encoder}; NaN when there is no such encoder.
     */
    public float resolution(int index) {
        Sensor e = index >= 1 && index <= MAX_INDEX ? encoders[index - 1] : null;
        return e == null ? Float.NaN : e.get_resolution();
    }

    /** Writes the encoder angle of encoder index (1..4) in degrees, or NaN if absent, without allocating. */
    public float angle(int index) {
        Sensor e = index >= 1 && index <= MAX_INDEX ? encoders[index - 1] : null;
        return e == null ? Float.NaN : e.get_value();
    }

    /** The analog input values in the order the pins were added (a new array). */
    public float[] get_sensor_data() {
        float[] out = new float[analogs.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = analogs.get(i).get_value();
        }
        return out;
    }

    /**
     * Runs the mechanism's forward kinematics on angles in degrees (a 3-element PVector.array() is fine) and
     * returns the end-effector position {x, y} in metres.
     */
    public float[] get_device_position(float[] angles) {
        requireMechanism("get_device_position");
        mechanism.forwardKinematics(angles);
        return mechanism.get_coordinate();
    }

    /**
     * Runs the mechanism's torque calculation on an end-effector force in newtons (a 3-element
     * PVector.array() is fine), stores one torque per actuator in index order, and returns the torques.
     */
    public float[] set_device_torques(float[] forces) {
        requireMechanism("set_device_torques");
        mechanism.torqueCalculation(forces);
        float[] torques = mechanism.get_torque();
        int k = 0;
        for (Actuator a : actuators) {
            if (a != null && k < torques.length) {
                a.set_torque(torques[k++]);
            }
        }
        return torques;
    }

    /** Sets the torque (N m) of actuator index (1..4) directly, without the mechanism and without allocating. */
    public void set_actuator_torque(int index, float torque) {
        Actuator a = index >= 1 && index <= MAX_INDEX ? actuators[index - 1] : null;
        if (a == null) {
            throw new IllegalArgumentException(what() + ".set_actuator_torque: no actuator " + index);
        }
        a.set_torque(torque);
    }

    // ------------------------------------------------------------------------------------------ internals

    /** Sends zero torques and zero PWM from a message of its own (safe beside a loop using the write buffer). */
    void writeZeros() {
        byte[] zeros = zeroMessage();
        if (zeros != null) {
            board.sendTorques(zeros, zeros.length, false, null);
        }
    }

    /** The ports and pins this device uses, for messages: "motor ports 1, 2; encoder ports 1, 2". */
    String describePorts() {
        StringBuilder b = new StringBuilder();
        appendList(b, "motor ports", actuatorAtPort);
        appendList(b, "encoder ports", encoderAtPort);
        if (!analogs.isEmpty()) {
            b.append(b.length() > 0 ? "; " : "").append("analog pins");
            for (int i = 0; i < analogs.size(); i++) {
                b.append(i == 0 ? " A" : ", A").append(analogs.get(i).get_port() - WireFormat.ANALOG_PIN_BASE);
            }
        }
        if (!pwms.isEmpty()) {
            b.append(b.length() > 0 ? "; " : "").append("PWM pins");
            for (int i = 0; i < pwms.size(); i++) {
                b.append(i == 0 ? " " : ", ").append(pwms.get(i).get_pin());
            }
        }
        return b.length() == 0 ? "no ports" : b.toString();
    }

    /** The motor and encoder ports both devices use, for messages ("motor ports 1, 2; encoder port 1"), or "". */
    static String sharedPorts(Device a, Device b) {
        int n = Math.min(a.ports, b.ports);
        int[] motors = new int[n];
        int[] encoders = new int[n];
        for (int p = 0; p < n; p++) {
            motors[p] = a.actuatorAtPort[p] != 0 && b.actuatorAtPort[p] != 0 ? 1 : 0;
            encoders[p] = a.encoderAtPort[p] != 0 && b.encoderAtPort[p] != 0 ? 1 : 0;
        }
        StringBuilder s = new StringBuilder();
        appendList(s, "motor ports", motors);
        appendList(s, "encoder ports", encoders);
        return s.toString();
    }

    private static void appendList(StringBuilder b, String what, int[] atPort) {
        int first = b.length();
        for (int p = 0; p < atPort.length; p++) {
            if (atPort[p] != 0) {
                b.append(b.length() == first ? (first > 0 ? "; " : "") + what + " " : ", ").append(p + 1);
            }
        }
    }

    /**
     * Length in bytes of this device's reply to a write (0 before the setup). Not API: for the motor guard in
     * {@code tactus.haptics.safety}.
     */
    public int replyBytes() {
        return frame == null ? 0 : WireFormat.replyLength(frame.length);
    }

    /**
     * The write message with zero torques and zero PWM, or null before the setup. Not API: for the motor guard in
     * {@code tactus.haptics.safety}.
     */
    public byte[] zeroMessage() {
        return zeroMessage;
    }

    private void sendWrite() {
        for (int i = 0; i < nPwm; i++) {
            pwmValues[i] = pwms.get(i).get_value();
        }
        WireFormat.encodeWrite(id, pwmValues, nPwm, torquesByPort, nMotors, writeBuffer);
        boolean nonZero = false;
        for (int i = 0; i < nMotors; i++) {
            nonZero |= torquesByPort[i] != 0f;
        }
        board.sendTorques(writeBuffer, writeBuffer.length, nonZero, zeroMessage);
    }

    private Pwm pwmAt(String op, int pin) {
        for (Pwm p : pwms) {
            if (p.get_pin() == pin) {
                return p;
            }
        }
        throw new IllegalArgumentException(op + ": pin " + pin + " was not added with add_pwm_pin");
    }

    private String what() {
        return "Device(id " + (id & 0xFF) + ")";
    }

    private void requireUnconfigured(String op) {
        if (configured) {
            throw new IllegalStateException(op + ": the setup was already sent; the board would misread every "
                    + "later message if the configuration changed now");
        }
    }

    private void requireConfigured(String method) {
        if (!configured) {
            throw new IllegalStateException(what() + "." + method + ": call device_set_parameters() first; an unconfigured board "
                    + "reads the torque bytes as commands");
        }
    }

    private void requireMechanism(String method) {
        if (mechanism == null) {
            throw new IllegalStateException(what() + "." + method + ": no mechanism; call set_mechanism() first");
        }
    }

    private static void checkIndex(String op, String what, int index) {
        if (index < 1 || index > MAX_INDEX) {
            throw new IllegalArgumentException(op + ": " + what + " index must be 1.." + MAX_INDEX + ", got " + index);
        }
    }

    private static void checkRotation(String op, int rotation) {
        if (rotation != 0 && rotation != 1) {
            throw new IllegalArgumentException(op + ": rotation must be 0 (CW) or 1 (CCW), got " + rotation);
        }
    }

    private void checkPort(String op, int port) {
        if (port < 1 || port > ports) {
            throw new IllegalArgumentException(op + ": port must be 1.." + ports + " on a " + board.model()
                    + " board, got " + port);
        }
    }

    /**
     * The firmware stores the k-th rotation byte in port k's slot whatever the mask says, so a CCW rotation on
     * a port set that is not 1..k would land on the wrong port.
     */
    private void checkFirmwareDirectionSlots(String op) {
        checkSlots(op, "actuator", actuatorAtPort, true);
        checkSlots(op, "encoder", encoderAtPort, false);
    }

    private void checkSlots(String op, String what, int[] atPort, boolean motors) {
        int k = 0;
        for (int p = 0; p < ports; p++) {
            if (atPort[p] != 0) {
                int dir = motors ? actuators[atPort[p] - 1].get_direction() : encoders[atPort[p] - 1].get_direction();
                if (k != p && dir == 1) {
                    throw new IllegalArgumentException(op + ": " + what + " " + atPort[p] + " on port " + (p + 1)
                            + " with rotation CCW: the firmware would apply the rotation to port " + (k + 1)
                            + "; use ports 1.." + (k + 1) + " or rotation CW");
                }
                k++;
            }
        }
    }
}
