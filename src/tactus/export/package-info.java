/**
 * Writing a model as code for other systems: Faust first.
 *
 * <p>{@link tactus.export.FaustExporter} writes a {@link tactus.PhysicalModel} as it is now (positions,
 * velocities, pending forces, parameters in per-step values, gravity and air friction) as a Faust {@code .dsp}
 * program. 1-D models ({@code Mass1D}, {@code Osc1D}, {@code Ground1D}, {@code SpringDamper1D}, and contacts
 * along z) use the primitives of Faust's {@code mi.lib}; any other model is written as the explicit 3-D scheme
 * (three recursive signals per mass, distance-based interactions). What to listen to, which masses take a force
 * input and which parameters become sliders is said in {@link tactus.export.FaustExportOptions}. This package
 * reads the model through the public facade only (package {@code tactus}).
 */
package tactus.export;
