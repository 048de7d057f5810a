/**
 * Emulators, so that every haptic code path runs and is tested without hardware. A Haply board emulator: the
 * firmware side of the V2 protocol (setup, torque to PWM, quantised encoders, one reply per write), a simulated
 * pantograph moved by a scripted, spring-driven or target-following hand, reachable in-process
 * ({@link tactus.haptics.emulator.BoardEmulator#connect()}) or over a pseudo-terminal
 * ({@link tactus.haptics.emulator.PtyPair}) so that the serial code path runs without hardware. And an emulator of
 * Haply's Inverse Service ({@link tactus.haptics.emulator.InverseServiceEmulator}): a WebSocket server on
 * localhost speaking the service's JSON, with a simulated 3-DoF Inverse3 ({@link tactus.haptics.emulator.SimulatedInverse3})
 * moved by a {@link tactus.haptics.emulator.Hand3D} and optionally a VerseGrip; in-process for tests, or standalone
 * on the service's port ({@code gradle inverseEmulator}).
 */
package tactus.haptics.emulator;
