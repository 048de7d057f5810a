/**
 * Off-screen drawing helpers that need only Processing's core and no running sketch.
 *
 * <p>{@link tactus.render.LinePlot} draws line charts (several named series, linear or logarithmic axes)
 * into an off-screen {@code processing.awt.PGraphicsJava2D} image. It works in headless mode
 * ({@code -Djava.awt.headless=true}), so tests, the demo and accuracy reports can write PNG files on a
 * machine without a display. In a sketch, the image returned by
 * {@link tactus.render.LinePlot#render(int, int)} can be drawn with {@code image()}.
 */
package tactus.render;
