package tactus.haptics;

/**
 * An encoder or analog input of a {@link Device}: index, rotation (0 = CW, 1 = CCW), offset (degrees),
 * resolution (counts per turn as sent to the board), port, and the last value read (degrees for an encoder).
 */
public class Sensor {
    private int encoder;
    private int direction;
    private float offset;
    private float resolution;
    private int port;
    private float value;

    /** Creates an unassigned sensor. */
    public Sensor() {
    }

    /** Creates a sensor with an index, rotation, offset (degrees), resolution and board port. */
    public Sensor(int encoder, int direction, float offset, float resolution, int port) {
        this.encoder = encoder;
        this.direction = direction;
        this.offset = offset;
        this.resolution = resolution;
        this.port = port;
    }

    /** Sets the encoder index. */
    public void set_encoder(int encoder) {
        this.encoder = encoder;
    }

    /** Sets the rotation (0 = CW, 1 = CCW). */
    public void set_direction(int direction) {
        this.direction = direction;
    }

    /** Sets the offset in degrees. */
    public void set_offset(float offset) {
        this.offset = offset;
    }

    /** Sets the resolution (counts per turn as sent to the board). */
    public void set_resolution(float resolution) {
        this.resolution = resolution;
    }

    /** Sets the board port (for analog inputs: the Arduino Due pin number 54 + n). */
    public void set_port(int port) {
        this.port = port;
    }

    /** Sets the last value read. */
    public void set_value(float value) {
        this.value = value;
    }

    /** The encoder index. */
    public int get_encoder() {
        return encoder;
    }

    /** The rotation (0 = CW, 1 = CCW). */
    public int get_direction() {
        return direction;
    }

    /** The offset in degrees. */
    public float get_offset() {
        return offset;
    }

    /** The resolution. */
    public float get_resolution() {
        return resolution;
    }

    /** The board port. */
    public int get_port() {
        return port;
    }

    /** The last value read (degrees for an encoder, raw ADC counts for an analog input). */
    public float get_value() {
        return value;
    }
}
