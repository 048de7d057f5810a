/**
 * Stable contact with stiff models: the passivity observer the loop keeps
 * ({@link tactus.haptics.passivity.PassivityObserver}, {@code loop.passivity()}), the time-domain passivity
 * controller that damps what the observer sees the port give the hand, the
 * {@link tactus.haptics.passivity.VirtualCoupling} between handle and avatar, and
 * {@link tactus.haptics.passivity.FrictionCompensation}. A sketch switches them on through the
 * {@link tactus.haptics.HapticLoop} ({@code setPassivityControl}, {@code setVirtualCoupling},
 * {@code setFrictionCompensation}); {@link tactus.haptics.passivity.HapticPort}, which chains them between the
 * device and the avatar, is marked "Not API".
 */
package tactus.haptics.passivity;
