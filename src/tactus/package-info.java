/**
 * Tactus: mass-interaction physics for Processing, to see, hear and touch virtual objects.
 *
 * <p>{@link tactus.PhysicalModel} is the entry point. Masses ({@link tactus.Mass3D},
 * {@link tactus.Ground3D}, {@link tactus.Osc3D}, ...) and interactions
 * ({@link tactus.SpringDamper3D}, {@link tactus.Contact3D}, {@link tactus.Bubble3D},
 * {@link tactus.PlaneContact3D}, ...) are added by name and returned as handles. The model
 * steps with the explicit scheme of mass-interaction physics at a fixed simulation rate.
 */
package tactus;
