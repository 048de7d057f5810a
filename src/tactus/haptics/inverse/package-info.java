/**
 * Haply's current devices (Inverse3, Inverse3x, Minverse, with or without a VerseGrip handle) through Haply's
 * Inverse Service: a local program, shipped with the Haply Hub, that an application talks to in JSON over a
 * WebSocket ({@code ws://localhost:10001} by default). {@link tactus.haptics.inverse.InverseServiceClient} keeps
 * the socket (the JDK's {@code java.net.http.WebSocket}) and parses each state frame with Jackson's streaming
 * parser into an {@link tactus.haptics.inverse.InverseState}; {@link tactus.haptics.inverse.Inverse3Device}
 * makes it a {@link tactus.haptics.HapticDevice} for the {@link tactus.haptics.HapticLoop}. The emulator of the
 * service is {@link tactus.haptics.emulator.InverseServiceEmulator}. {@link tactus.haptics.inverse.InverseGuard}
 * is a process beside the sketch's JVM that sends zero force through a session of its own when that JVM is killed
 * or paused ({@link tactus.haptics.inverse.Inverse3Device#openGuarded}); an Inverse3Device can also reconnect to a
 * restarted service ({@link tactus.haptics.inverse.Inverse3Device#setReconnect}).
 *
 * <p>Units: positions in metres, velocities in metres per second, forces in newtons, along the service's axes;
 * orientations as unit quaternions (w, x, y, z).
 */
package tactus.haptics.inverse;
