package tactus.haptics;

/** A motor of a {@link Device}: its index (1..4), rotation (0 = CW, 1 = CCW), board port and torque (N m). */
public class Actuator {
    private int actuator;
    private int direction;
    private int port;
    private float torque;

    /** Creates an unassigned actuator. */
    public Actuator() {
    }

    /** Creates an actuator with an index, a rotation (0 = CW, 1 = CCW) and a board port. */
    public Actuator(int actuator, int direction, int port) {
        this.actuator = actuator;
        this.direction = direction;
        this.port = port;
    }

    /** Sets the actuator index. */
    public void set_actuator(int actuator) {
        this.actuator = actuator;
    }

    /** Sets the rotation (0 = CW, 1 = CCW). */
    public void set_direction(int direction) {
        this.direction = direction;
    }

    /** Sets the board port. */
    public void set_port(int port) {
        this.port = port;
    }

    /** Sets the torque in N m. */
    public void set_torque(float torque) {
        this.torque = torque;
    }

    /** The actuator index. */
    public int get_actuator() {
        return actuator;
    }

    /** The rotation (0 = CW, 1 = CCW). */
    public int get_direction() {
        return direction;
    }

    /** The board port. */
    public int get_port() {
        return port;
    }

    /** The torque in N m. */
    public float get_torque() {
        return torque;
    }
}
