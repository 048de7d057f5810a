/**
 * Haply haptics: an hAPI-compatible device layer ({@link tactus.haptics.Board},
 * {@link tactus.haptics.Device}, {@link tactus.haptics.Mechanisms}, {@link tactus.haptics.Pantograph},
 * {@link tactus.haptics.Actuator}, {@link tactus.haptics.Sensor}, {@link tactus.haptics.Pwm}) that speaks
 * the Haply V2 wire protocol over a {@link tactus.haptics.transport.Transport}, pantograph kinematics with
 * hardware presets, and port discovery; the fixed-rate {@link tactus.haptics.HapticLoop} with its telemetry
 * and safety; and {@link tactus.haptics.HapticSession}, which gives a sketch a Haply (or the emulator, with
 * the mouse as the hand) and a loop in a few lines. A board on a serial port starts a
 * {@link tactus.haptics.safety.MotorGuard} process that zeroes the motors if the JVM ends without closing the board.
 *
 * <p>The loop drives any {@link tactus.haptics.HapticDevice} (metres in, newtons out): the 2DIY as a
 * {@link tactus.haptics.pantograph.PantographDevice}, or Haply's 3-DoF Inverse3 family through the Inverse Service
 * ({@code tactus.haptics.inverse}), through a {@link tactus.haptics.WorkspaceMapping} (axes, handedness, scale,
 * offset). {@link tactus.haptics.HapticSession3D} gives a 3-D sketch an Inverse3, a 2DIY or the emulated Inverse3;
 * {@link tactus.haptics.HapticSession} finds an Inverse3 first too, and drives it in its vertical plane.
 *
 * <p>A sketch written for hAPI 2.x ports by deleting the hAPI {@code .java} files from its folder and
 * adding {@code import tactus.haptics.*;}. Such a sketch keeps a safety net without calling anything new:
 * the {@link tactus.haptics.Board} zeroes the motors when its torque writes stop (50 ms by default), declares
 * a board that stops reading lost within a second, never lets a write block without a bound, and prints each
 * kind of failure once where it happens. The board emulator lives in {@code tactus.haptics.emulator}.
 *
 * <p>This package holds what a sketch names: the hAPI-compatible classes, the loop, the sessions, the devices and
 * avatars. The rest sits in rooms beside it: {@code transport} (serial ports and the wire format), {@code safety}
 * (the motor guard and its heartbeat), {@code loop} (the loop's machinery and the decoupled avatar), {@code passivity}
 * (observer, controller, virtual coupling, friction compensation), {@code session} (what the sessions share),
 * {@code pantograph} (the 2DIY's kinematics and device), {@code inverse} (the Inverse3 family) and {@code emulator}.
 * A public class or member marked "Not API" is public only so that another room can reach it.
 */
package tactus.haptics;
