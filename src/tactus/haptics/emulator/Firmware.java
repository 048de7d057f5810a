package tactus.haptics.emulator;

import tactus.haptics.BoardModel;
import tactus.haptics.transport.WireFormat;

/**
 * The firmware side of the Haply V2 protocol, as the M0 V0.3 / M3 V1.5 / Dev-Kit V0.4 firmware behaves:
 * one command handled per pass; single-byte fields read without waiting (a byte that has not arrived reads
 * as 0xFF); the encoder-parameter and torque blocks wait for their bytes; the k-th rotation byte lands in
 * port k's slot whatever the mask; a reset clears assignments but not the motor duty; a setup zeroes the
 * duty of the ports it configures and presets the encoders at the current pose; a write for another id than
 * the configured one is answered with its id alone and its payload is then read as commands; a write with
 * id 0 (the firmware's "unassigned" marker) claims every free PWM pin, free motor, free analog slot and free
 * encoder, as the firmware does (reading an encoder that was never set up is a null pointer there: the
 * emulated board then stops, as after a HardFault); unknown bytes are dropped one at a time. One configured
 * device at a time.
 */
final class Firmware {
    /** What the firmware drives and reads. */
    interface Hardware {
        /** Physical angle in degrees of the joint whose encoder is on this port (1-based). */
        double jointDeg(int port);

        /** Applies a physical motor torque (N m, in the joint's angle sense) on this port. */
        void motorTorque(int port, double torque);

        /** Raw ADC value of analog input An. */
        double analog(int n);

        /** Called before a write is answered, so the physics can catch up with time. */
        void beforeWrite();
    }

    /** Where replies go. */
    interface Output {
        void write(byte[] data, int off, int len);
    }

    private static final int SLOTS = 4;
    /** Analog slots of the M0 firmware's table (A0..A4). */
    private static final int M0_ANALOG_SLOTS = 5;
    private static final int PWM_PINS = 14;
    private static final long BLOCK_WAIT_NANOS = 1_000_000_000L;

    private final BoardModel model;
    private final ByteRing in;
    private final Hardware hw;
    private final Output out;

    private final int[] motorRotSlot = new int[SLOTS];
    private final int[] encRotSlot = new int[SLOTS];
    private final int[] motorMount = {-1, -1, -1, -1};
    private final int[] encMount = {-1, -1, -1, -1};
    private final boolean[] motorOn = new boolean[SLOTS];
    private final boolean[] encOn = new boolean[SLOTS];
    private final int[] duty = new int[SLOTS];
    private final boolean[] dirHigh = new boolean[SLOTS];
    private final int[] encPreset = new int[SLOTS];
    private final float[] encRes = new float[SLOTS];
    private final double[] encSetupDeg = new double[SLOTS];
    private int configuredId = -1;
    private int[] sensors = new int[0];     // analog n per reply slot
    private int[] pwmPins = new int[0];
    private final int[] pwmPulse = new int[PWM_PINS];
    private final boolean[] analogEverSetUp = new boolean[12];
    private boolean claim;                  // the pending write has id 0 and claims the free slots
    private boolean hardFault;

    // a command waiting for its float block
    private int pendingType = -1;
    private int pendingId;
    private int pendingMotorMask;
    private int pendingEncMask;
    private int[] pendingSensors;
    private int[] pendingPwm;
    private int[] pendingIntendedMotor;
    private int[] pendingIntendedEnc;
    private byte[] block = new byte[64];
    private byte[] replyBuffer = new byte[64];
    private int blockNeed;
    private int blockHave;
    private long blockDeadline;

    long setups;
    long resets;
    long writes;
    long foreignWrites;
    long unknownBytes;
    long lateBytes;
    long replies;

    Firmware(BoardModel model, ByteRing in, Hardware hw, Output out) {
        this.model = model;
        this.in = in;
        this.hw = hw;
        this.out = out;
    }

    /** One pass of the firmware loop: handles at most one command. Returns true if a byte was consumed. */
    boolean pass(long nowNanos) {
        if (hardFault) {
            in.take(new byte[256], 0, 256);   // a faulted board reads nothing: the bytes are lost
            return false;
        }
        if (pendingType >= 0) {
            return continueBlock(nowNanos);
        }
        int type = in.take();
        if (type < 0) {
            return false;
        }
        switch (type) {
            case WireFormat.RESET:
                readNow();
                reset();
                resets++;
                return true;
            case WireFormat.SETUP:
                startSetup(nowNanos);
                return true;
            case WireFormat.WRITE:
                startWrite(nowNanos);
                return true;
            default:
                unknownBytes++;
                return true;
        }
    }

    private int readNow() {
        int b = in.take();
        if (b < 0) {
            lateBytes++;
            return 0xFF;
        }
        return b;
    }

    private void reset() {
        configuredId = -1;
        for (int p = 0; p < SLOTS; p++) {
            motorOn[p] = false;
            encOn[p] = false;
        }
        sensors = new int[0];
        pwmPins = new int[0];
        // the duty registers keep their value: a reset does not stop the motors
    }

    private void startSetup(long now) {
        pendingId = readNow();
        int portBits = (1 << model.ports()) - 1;
        pendingMotorMask = readNow() & portBits;
        pendingIntendedMotor = new int[] {-1, -1, -1, -1};
        int k = 0;
        for (int p = 0; p < SLOTS; p++) {
            if ((pendingMotorMask & (1 << p)) != 0) {
                int rot = readNow();
                motorRotSlot[k] = rot;          // k-th byte into slot k, whatever the mask says
                pendingIntendedMotor[p] = rot;
                k++;
            }
        }
        pendingEncMask = readNow() & portBits;
        pendingIntendedEnc = new int[] {-1, -1, -1, -1};
        k = 0;
        for (int p = 0; p < SLOTS; p++) {
            if ((pendingEncMask & (1 << p)) != 0) {
                int rot = readNow();
                encRotSlot[k] = rot;
                pendingIntendedEnc[p] = rot;
                k++;
            }
        }
        int ns = readNow();
        int[] sens = new int[ns];
        int kept = 0;
        for (int i = 0; i < ns; i++) {
            int n = analogIndex(readNow());
            if (n >= 0) {
                sens[kept++] = n;
            }
        }
        pendingSensors = java.util.Arrays.copyOf(sens, kept);
        int np = readNow();
        int[] pins = new int[np];
        int keptPins = 0;
        for (int i = 0; i < np; i++) {
            int pin = readNow();
            if (pin <= 13) {
                pins[keptPins++] = pin;
            }
        }
        pendingPwm = java.util.Arrays.copyOf(pins, keptPins);
        startBlock(WireFormat.SETUP, 8 * Integer.bitCount(pendingEncMask), now);
    }

    /** The analog index n the firmware reads for wire pin byte b, or -1 if it drops it. */
    private int analogIndex(int b) {
        if (model == BoardModel.M0) {
            int pin = b - 40;               // Due numbering to Zero numbering: A0 = 14
            if (pin < 14 || pin > 19) {
                return -1;
            }
            return pin - 14;
        }
        int n = b - WireFormat.ANALOG_PIN_BASE;
        return n >= 0 && n <= model.maxAnalogPin() ? n : -1;
    }

    private void startWrite(long now) {
        int id = readNow();
        if (id == 0 && configuredId != 0) {
            startClaimingWrite(now);
            return;
        }
        if (id != configuredId) {
            foreignWrites++;
            out.write(new byte[] {(byte) id}, 0, 1);
            replies++;
            return;                          // the payload is read as commands from here on
        }
        pendingId = id;
        claim = false;
        for (int pin : pwmPins) {
            pwmPulse[pin] = readNow();
        }
        int motors = 0;
        for (int p = 0; p < SLOTS; p++) {
            if (motorOn[p]) {
                motors++;
            }
        }
        startBlock(WireFormat.WRITE, 4 * motors, now);
    }

    /** A write with id 0: every slot no device holds answers to it (id 0 is the firmware's "unassigned"). */
    private void startClaimingWrite(long now) {
        pendingId = 0;
        claim = true;
        for (int pin = 0; pin < PWM_PINS; pin++) {
            if (!contains(pwmPins, pin)) {
                pwmPulse[pin] = readNow();
            }
        }
        int motors = 0;
        for (int p = 0; p < model.ports(); p++) {
            if (!motorOn[p]) {
                motors++;
            }
        }
        startBlock(WireFormat.WRITE, 4 * motors, now);
    }

    private static boolean contains(int[] values, int v) {
        for (int x : values) {
            if (x == v) {
                return true;
            }
        }
        return false;
    }

    private void startBlock(int type, int need, long now) {
        pendingType = type;
        if (block.length < need) {
            block = new byte[need];
        }
        blockNeed = need;
        blockHave = 0;
        blockDeadline = now + BLOCK_WAIT_NANOS;
        continueBlock(now);
    }

    private boolean continueBlock(long now) {
        int before = blockHave;
        blockHave += in.take(block, blockHave, blockNeed - blockHave);
        if (blockHave > before) {
            blockDeadline = now + BLOCK_WAIT_NANOS;
        }
        if (blockHave < blockNeed) {
            if (now - blockDeadline < 0) {
                return blockHave > before;
            }
            while (blockHave < blockNeed) {  // gave up waiting: the missing bytes read as 0xFF
                block[blockHave++] = (byte) 0xFF;
                lateBytes++;
            }
        }
        int type = pendingType;
        pendingType = -1;
        if (type == WireFormat.SETUP) {
            applySetup();
        } else {
            applyWrite();
        }
        return true;
    }

    private void applySetup() {
        configuredId = pendingId;
        for (int p = 0; p < SLOTS; p++) {
            motorOn[p] = (pendingMotorMask & (1 << p)) != 0;
            if (motorOn[p]) {
                duty[p] = 0;
                dirHigh[p] = false;
                if (motorMount[p] < 0) {
                    motorMount[p] = pendingIntendedMotor[p];
                }
            }
        }
        int k = 0;
        for (int p = 0; p < SLOTS; p++) {
            encOn[p] = (pendingEncMask & (1 << p)) != 0;
            if (encOn[p]) {
                float offset = WireFormat.getFloat(block, 8 * k);
                float res = WireFormat.getFloat(block, 8 * k + 4);
                float eff = model == BoardModel.M0 ? res / 2f : res;   // the M0 counts at half the rate
                encRes[p] = eff;
                encPreset[p] = (int) (offset * eff / 360f);
                encSetupDeg[p] = hw.jointDeg(p + 1);
                if (encMount[p] < 0) {
                    encMount[p] = pendingIntendedEnc[p];
                }
                k++;
            }
        }
        sensors = pendingSensors;
        for (int n : sensors) {
            analogEverSetUp[n] = true;
        }
        pwmPins = pendingPwm;
        setups++;
    }

    private void applyWrite() {
        writes++;
        int k = 0;
        for (int p = 0; p < SLOTS; p++) {
            if (claim ? p >= model.ports() || motorOn[p] || motorMount[p] < 0 : !motorOn[p]) {
                if (claim && p < model.ports() && !motorOn[p]) {
                    k++;   // a free motor never set up: its float is read, its pins are not wired
                }
                continue;
            }
            float tau = WireFormat.getFloat(block, 4 * k++);
            int rot = motorRotSlot[p];
            if (model.invertsEvenMotorPorts() && (p == 1 || p == 3)) {
                rot = 1 - rot;
            }
            if (Float.isNaN(tau)) {
                duty[p] = 0;
            } else {
                float mag = Math.min(Math.abs(tau), (float) BoardModel.MAX_TORQUE);
                // the product is a float, the division by the firmware's double constant MAX_TORQUE is in double
                duty[p] = (int) ((float) (model.pwmResolution() * mag) / BoardModel.MAX_TORQUE);
            }
            boolean low = (tau > 0) ^ (rot == 1);
            dirHigh[p] = !low;
        }
        hw.beforeWrite();
        for (int p = 0; p < SLOTS; p++) {
            hw.motorTorque(p + 1, physicalTorque(p));
        }
        if (claim) {
            replyToClaim();
        } else {
            reply();
        }
    }

    /** The reply to an id-0 write: id 0, then every free analog slot, then every free encoder. */
    private void replyToClaim() {
        int analogSlots = model == BoardModel.M0 ? M0_ANALOG_SLOTS : model.maxAnalogPin() + 1;
        int n = 0;
        for (int a = 0; a < analogSlots; a++) {
            if (!contains(sensors, a)) {
                n++;
            }
        }
        for (int p = 0; p < model.ports(); p++) {
            if (!encOn[p]) {
                if (encMount[p] < 0) {
                    hardFault = true;   // the firmware reads an encoder object that was never created
                    return;
                }
                n++;
            }
        }
        int len = WireFormat.replyLength(n);
        if (replyBuffer.length < len) {
            replyBuffer = new byte[len];
        }
        byte[] r = replyBuffer;
        r[0] = 0;
        int k = 1;
        for (int a = 0; a < analogSlots; a++) {
            if (!contains(sensors, a)) {
                boolean read = analogEverSetUp[a] && (model != BoardModel.M0 || a == 1 || a == 2);
                WireFormat.putFloat(r, k, read ? (float) hw.analog(a) : 0f);
                k += 4;
            }
        }
        for (int p = 0; p < model.ports(); p++) {
            if (!encOn[p]) {
                WireFormat.putFloat(r, k, angle(p));
                k += 4;
            }
        }
        out.write(r, 0, len);
        replies++;
    }

    /** True once the emulated firmware has faulted (an id-0 write read an encoder never set up). */
    boolean hardFault() {
        return hardFault;
    }

    private void reply() {
        int nEnc = 0;
        for (int p = 0; p < SLOTS; p++) {
            if (encOn[p]) {
                nEnc++;
            }
        }
        int len = WireFormat.replyLength(sensors.length + nEnc);
        if (replyBuffer.length < len) {
            replyBuffer = new byte[len];
        }
        byte[] r = replyBuffer;
        r[0] = (byte) pendingId;
        int k = 1;
        for (int n : sensors) {
            float v = (model == BoardModel.M0 && n != 1 && n != 2) ? 0f : (float) hw.analog(n);
            WireFormat.putFloat(r, k, v);
            k += 4;
        }
        for (int p = 0; p < SLOTS; p++) {
            if (encOn[p]) {
                WireFormat.putFloat(r, k, angle(p));
                k += 4;
            }
        }
        out.write(r, 0, len);
        replies++;
    }

    /** The angle in degrees the encoder on slot p reports now. */
    float angle(int p) {
        double now = hw.jointDeg(p + 1);
        int sign = encRotSlot[p] == encMount[p] ? 1 : -1;
        // quadrature edges; the 1e-9 count keeps round-off of the simulated pose from flipping an edge
        long moved = (long) Math.floor(now * encRes[p] / 360.0 + 1e-9)
                - (long) Math.floor(encSetupDeg[p] * encRes[p] / 360.0 + 1e-9);
        long count = encPreset[p] + sign * moved;
        return 360f * count / encRes[p];
    }

    /** Physical torque (N m, joint sense) the motor on slot p produces from its duty and direction pin. */
    double physicalTorque(int p) {
        if (motorMount[p] < 0) {
            return 0;
        }
        double mag = duty[p] * BoardModel.MAX_TORQUE / model.pwmResolution();
        double pin = dirHigh[p] ? -1 : 1;
        double mount = motorMount[p] == 1 ? -1 : 1;
        return mag * pin * mount + 0.0;   // never -0.0
    }

    int duty(int port) {
        return duty[port - 1];
    }

    boolean directionHigh(int port) {
        return dirHigh[port - 1];
    }

    int pwmPulse(int pin) {
        return pwmPulse[pin];
    }

    int configuredId() {
        return configuredId;
    }
}
