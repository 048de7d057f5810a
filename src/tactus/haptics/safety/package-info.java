/**
 * What keeps the motors safe when the sketch's JVM cannot: the {@link tactus.haptics.safety.MotorGuard}, a small
 * process that zeroes a 2DIY's motors when the JVM ends or stops without closing its board, and the pieces the
 * guards share (the heartbeat in shared memory, the starting of a guard process, the watch over a paused JVM).
 * A board starts its guard by itself; a sketch never calls this package. The classes marked "Not API" are public
 * only so that {@link tactus.haptics.Board} and the Inverse3's guard in {@code tactus.haptics.inverse} can reach them.
 */
package tactus.haptics.safety;
