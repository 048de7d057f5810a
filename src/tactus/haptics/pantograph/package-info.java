/**
 * The 2-DoF Haply pantograph (the 2DIY and the 2018 dev kit) in metres and newtons: its kinematics in double precision
 * ({@link tactus.haptics.pantograph.PantographKinematics}: forward, inverse, J^T F) and the
 * {@link tactus.haptics.pantograph.PantographDevice}, the {@link tactus.haptics.HapticDevice} every
 * {@link tactus.haptics.HapticLoop} over a 2DIY runs through. The hAPI-compatible names a ported sketch uses
 * ({@link tactus.haptics.Pantograph}, {@link tactus.haptics.Mechanisms}) stay in {@code tactus.haptics}.
 */
package tactus.haptics.pantograph;
