/**
 * Drawing with Processing's core: models and charts.
 *
 * <p>{@link tactus.render.ModelDrawer} is the generic model renderer behind {@link tactus.ModelRenderer}: it
 * draws any {@link tactus.PhysicalModel} into any {@code PGraphics}, 3D (P3D) or 2D (JAVA2D), from the model's
 * lock-free snapshot, with a {@link tactus.render.RenderStyle} per mass and interaction type (colour, size, mass
 * scaling, stroke weight, strain gradient) and replaceable {@link tactus.render.MassPainter} and
 * {@link tactus.render.LinkPainter}. It allocates nothing per frame once a topology has been drawn.
 *
 * <p>{@link tactus.render.LinePlot} draws line charts (several named series, linear or logarithmic axes)
 * into an off-screen {@code processing.awt.PGraphicsJava2D} image. It works in headless mode
 * ({@code -Djava.awt.headless=true}), so tests, the demo and accuracy reports can write PNG files on a
 * machine without a display. In a sketch, the image returned by
 * {@link tactus.render.LinePlot#render(int, int)} can be drawn with {@code image()}.
 */
package tactus.render;
