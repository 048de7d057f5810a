/**
 * A Haply board emulator: the firmware side of the V2 protocol (setup, torque to PWM, quantised encoders,
 * one reply per write), a simulated pantograph moved by a scripted, spring-driven or target-following hand,
 * reachable in-process ({@link tactus.haptics.emulator.BoardEmulator#connect()}) or over a pseudo-terminal
 * ({@link tactus.haptics.emulator.PtyPair}) so that the serial code path runs without hardware.
 */
package tactus.haptics.emulator;
