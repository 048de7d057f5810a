package tactus.render;

import processing.core.PGraphics;
import tactus.matModuleType;

/**
 * Draws one mass. Replace the {@link ModelDrawer}'s painter to draw masses your own way; the drawer has already
 * applied the view (scale and zoom) to the position and radius, and skips masses whose colour is fully
 * transparent. Called on the drawing thread, between {@link #begin} and {@link #end}, once per mass per frame: it
 * should not allocate.
 */
public interface MassPainter {
    /**
     * Called once per frame before the first mass, inside the drawer's {@code pushStyle()}.
     *
     * @param g the target
     * @param count the number of masses in the frame
     */
    default void begin(PGraphics g, int count) {
    }

    /**
     * Draws mass {@code index}.
     *
     * @param g the target
     * @param index the mass's index in the model
     * @param type its type
     * @param x drawing x, in the target's units (pixels for an untransformed target)
     * @param y drawing y
     * @param z drawing z (ignored by 2D targets)
     * @param radius drawing radius, &gt; 0
     * @param argb fill colour, packed {@code 0xAARRGGBB}
     */
    void mass(PGraphics g, int index, matModuleType type, float x, float y, float z, float radius, int argb);

    /** Called once per frame after the last mass. */
    default void end(PGraphics g) {
    }
}
