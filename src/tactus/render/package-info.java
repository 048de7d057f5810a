/**
 * Drawing models into a Processing {@code PGraphics} (JAVA2D and P3D).
 *
 * <p>This is where the generic model renderer lives. Charts of measured data (the demo's and the reports'
 * plots) are not drawn here: they belong to the tools source set ({@code tools/}), outside {@code Tactus.jar}.
 */
package tactus.render;
