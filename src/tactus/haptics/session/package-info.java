/**
 * What {@link tactus.haptics.HapticSession} and {@link tactus.haptics.HapticSession3D} share: the emulated hand
 * (the idle tour, then the mouse) and the status band a session draws. Not API: public only for the two sessions.
 */
package tactus.haptics.session;
