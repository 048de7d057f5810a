/**
 * Drawing models into a Processing {@code PGraphics} (JAVA2D, P2D and P3D).
 *
 * <p>{@link tactus.render.ModelDrawer} is the generic model renderer behind {@link tactus.ModelRenderer}: masses
 * and interactions by type ({@link tactus.render.RenderStyle}), or coloured by speed, force or strain
 * ({@link tactus.render.ColorBy}, {@link tactus.render.ColorScale}), and force arrows on haptic avatars. Every part
 * of the drawing can be replaced through {@link tactus.render.MassPainter}, {@link tactus.render.LinkPainter} and
 * {@link tactus.render.ArrowPainter}. It reads the model's lock-free snapshot and allocates nothing per element per
 * frame. {@link tactus.render.OrbitCamera} is a mouse camera (orbit, pan, zoom) so that sketches need no camera
 * library.
 *
 * <p>Charts of measured data (the demo's and the reports' plots) are not drawn here: they belong to the tools
 * source set ({@code tools/}), outside {@code Tactus.jar}.
 */
package tactus.render;
