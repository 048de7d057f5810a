package tactus.haptics.transport;

/**
 * The Haply V2 wire protocol: message codes and little-endian IEEE-754 float32 encoding.
 *
 * <p>Host to board: reset {@code [0][id]}; setup {@code [1][id][motorMask][motorDir...][encMask][encDir...]
 * [nSensors][pin...][nPwm][pwmPin...]([offset f32][resolution f32])...}; write {@code [2][id][pwm u8...]
 * [torque f32...]}. The board answers each write with {@code [id][sensor f32...][angle f32...]}. Masks,
 * directions, encoder parameters, torques and angles are in port order (port 1 = bit 0).
 */
public final class WireFormat {
    /** Message code of a reset. */
    public static final byte RESET = 0;
    /** Message code of a setup ({@code device_set_parameters}). */
    public static final byte SETUP = 1;
    /** Message code of a torque/PWM write (answered by one reply). */
    public static final byte WRITE = 2;
    /** Arduino Due pin number of analog input A0; "An" is sent as ANALOG_PIN_BASE + n. */
    public static final int ANALOG_PIN_BASE = 54;

    private WireFormat() {
    }

    /** Writes v as 4 little-endian bytes at b[off..off+3]. */
    public static void putFloat(byte[] b, int off, float v) {
        int bits = Float.floatToRawIntBits(v);
        b[off] = (byte) bits;
        b[off + 1] = (byte) (bits >>> 8);
        b[off + 2] = (byte) (bits >>> 16);
        b[off + 3] = (byte) (bits >>> 24);
    }

    /** Reads a little-endian float32 at b[off..off+3]. */
    public static float getFloat(byte[] b, int off) {
        int bits = (b[off] & 0xFF) | (b[off + 1] & 0xFF) << 8 | (b[off + 2] & 0xFF) << 16 | (b[off + 3] & 0xFF) << 24;
        return Float.intBitsToFloat(bits);
    }

    /** Length in bytes of the reply to a write: 1 + 4 * floats. */
    public static int replyLength(int floats) {
        return 1 + 4 * floats;
    }

    /** Length in bytes of a write message with nPwm PWM bytes and nMotors torques. */
    public static int writeLength(int nPwm, int nMotors) {
        return 2 + nPwm + 4 * nMotors;
    }

    /** Encodes a reset message {@code [0][id]}. */
    public static byte[] reset(byte id) {
        return new byte[] {RESET, id};
    }

    /**
     * Encodes a write message into out (length {@link #writeLength}): code, id, the PWM bytes in sorted pin
     * order, then the torques in port order. Returns the length.
     */
    public static int encodeWrite(byte id, int[] pwmValues, int nPwm, float[] torquesByPort, int nMotors, byte[] out) {
        out[0] = WRITE;
        out[1] = id;
        int p = 2;
        for (int i = 0; i < nPwm; i++) {
            out[p++] = (byte) pwmValues[i];
        }
        for (int i = 0; i < nMotors; i++) {
            putFloat(out, p, torquesByPort[i]);
            p += 4;
        }
        return p;
    }

    /**
     * Encodes a setup message.
     *
     * @param motorDirs rotation (0/1) of the motor on each port, or -1 where the port has no motor
     * @param encDirs rotation (0/1) of the encoder on each port, or -1 where the port has no encoder
     * @param encOffsets offset in degrees of the encoder on each port
     * @param encResolutions resolution of the encoder on each port
     * @param sensorPins wire pin numbers (54 + n) of the analog inputs, in the order they were added
     * @param pwmPins PWM pin numbers in ascending order
     */
    public static byte[] setup(byte id, int[] motorDirs, int[] encDirs, float[] encOffsets, float[] encResolutions,
                               int[] sensorPins, int[] pwmPins) {
        int nMotors = 0;
        int nEnc = 0;
        int motorMask = 0;
        int encMask = 0;
        for (int p = 0; p < motorDirs.length; p++) {
            if (motorDirs[p] >= 0) {
                motorMask |= 1 << p;
                nMotors++;
            }
        }
        for (int p = 0; p < encDirs.length; p++) {
            if (encDirs[p] >= 0) {
                encMask |= 1 << p;
                nEnc++;
            }
        }
        byte[] out = new byte[2 + 1 + nMotors + 1 + nEnc + 1 + sensorPins.length + 1 + pwmPins.length + 8 * nEnc];
        int k = 0;
        out[k++] = SETUP;
        out[k++] = id;
        out[k++] = (byte) motorMask;
        for (int dir : motorDirs) {
            if (dir >= 0) {
                out[k++] = (byte) dir;
            }
        }
        out[k++] = (byte) encMask;
        for (int dir : encDirs) {
            if (dir >= 0) {
                out[k++] = (byte) dir;
            }
        }
        out[k++] = (byte) sensorPins.length;
        for (int pin : sensorPins) {
            out[k++] = (byte) pin;
        }
        out[k++] = (byte) pwmPins.length;
        for (int pin : pwmPins) {
            out[k++] = (byte) pin;
        }
        for (int p = 0; p < encDirs.length; p++) {
            if (encDirs[p] >= 0) {
                putFloat(out, k, encOffsets[p]);
                putFloat(out, k + 4, encResolutions[p]);
                k += 8;
            }
        }
        return out;
    }
}
