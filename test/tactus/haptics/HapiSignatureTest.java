package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import processing.core.PApplet;

/** The public surface a ported hAPI 2.x sketch compiles against (haply-firmware-facts.md, the signature table). */
class HapiSignatureTest {

    private static void has(Class<?> c, Class<?> ret, String name, Class<?>... params) throws Exception {
        Method m = c.getMethod(name, params);
        assertEquals(ret, m.getReturnType(), c.getSimpleName() + "." + name);
        assertTrue(Modifier.isPublic(m.getModifiers()));
    }

    @Test
    void mechanismsIsAnAbstractClassWithExactlyHapisTenAbstractMethods() throws Exception {
        assertTrue(Modifier.isAbstract(Mechanisms.class.getModifiers()) && !Mechanisms.class.isInterface());
        assertTrue(Modifier.isPublic(Mechanisms.class.getConstructor().getModifiers()));
        Set<String> abstracts = new TreeSet<>();
        for (Method m : Mechanisms.class.getDeclaredMethods()) {
            if (Modifier.isAbstract(m.getModifiers())) {
                abstracts.add(m.getReturnType().getSimpleName() + " " + m.getName() + "("
                        + (m.getParameterCount() == 0 ? "" : m.getParameterTypes()[0].getSimpleName()) + ")");
            }
        }
        assertEquals(new TreeSet<>(Set.of("void forwardKinematics(float[])", "void torqueCalculation(float[])",
                "void forceCalculation()", "void positionControl()", "void inverseKinematics()",
                "void set_mechanism_parameters(float[])", "void set_sensor_data(float[])",
                "float[] get_coordinate()", "float[] get_torque()", "float[] get_angle()")), abstracts);
    }

    @Test
    void boardDeviceAndValueClassesHaveHapisSignatures() throws Exception {
        Board.class.getConstructor(PApplet.class, String.class, int.class);
        has(Board.class, void.class, "transmit", byte.class, byte.class, byte[].class, float[].class);
        has(Board.class, float[].class, "receive", byte.class, byte.class, int.class);
        has(Board.class, boolean.class, "data_available");
        Device.class.getConstructor(byte.class, Board.class);
        has(Device.class, void.class, "add_actuator", int.class, int.class, int.class);
        has(Device.class, void.class, "add_encoder", int.class, int.class, float.class, float.class, int.class);
        has(Device.class, void.class, "add_analog_sensor", String.class);
        has(Device.class, void.class, "add_pwm_pin", int.class);
        has(Device.class, void.class, "set_mechanism", Mechanisms.class);
        has(Device.class, void.class, "device_set_parameters");
        has(Device.class, void.class, "device_read_data");
        has(Device.class, void.class, "device_read_request");
        has(Device.class, void.class, "device_write_torques");
        has(Device.class, void.class, "set_pwm_pulse", int.class, float.class);
        has(Device.class, float.class, "get_pwm_pulse", int.class);
        has(Device.class, float[].class, "get_device_angles");
        has(Device.class, float[].class, "get_sensor_data");
        has(Device.class, float[].class, "get_device_position", float[].class);
        has(Device.class, float[].class, "set_device_torques", float[].class);
        Pantograph.class.getConstructor();
        Pantograph.class.getConstructor(int.class);
        Actuator.class.getConstructor();
        Actuator.class.getConstructor(int.class, int.class, int.class);
        for (String s : new String[] {"set_actuator", "set_direction", "set_port"}) {
            has(Actuator.class, void.class, s, int.class);
        }
        has(Actuator.class, void.class, "set_torque", float.class);
        has(Actuator.class, int.class, "get_actuator");
        has(Actuator.class, int.class, "get_direction");
        has(Actuator.class, int.class, "get_port");
        has(Actuator.class, float.class, "get_torque");
        Sensor.class.getConstructor();
        Sensor.class.getConstructor(int.class, int.class, float.class, float.class, int.class);
        for (String s : new String[] {"set_encoder", "set_direction", "set_port"}) {
            has(Sensor.class, void.class, s, int.class);
        }
        for (String s : new String[] {"set_offset", "set_resolution", "set_value"}) {
            has(Sensor.class, void.class, s, float.class);
        }
        has(Sensor.class, int.class, "get_encoder");
        has(Sensor.class, float.class, "get_offset");
        has(Sensor.class, float.class, "get_resolution");
        has(Sensor.class, float.class, "get_value");
        Pwm.class.getConstructor();
        Pwm.class.getConstructor(int.class, float.class);
        has(Pwm.class, void.class, "set_pin", int.class);
        has(Pwm.class, void.class, "set_pulse", float.class);
        has(Pwm.class, int.class, "get_pin");
        has(Pwm.class, int.class, "get_value");
        has(Pwm.class, float.class, "get_pulse");
    }
}
