package tactus.render;

import processing.core.PGraphics;
import tactus.matModuleType;

/**
 * Draws the force arrow of a mass (by default only of haptic avatars, {@link ModelDrawer#setForceArrow}).
 * Replace the {@link ModelDrawer}'s painter to draw arrows your own way; the drawer has already applied the view
 * and the arrow scale. Called on the drawing thread once per arrow per frame, after the masses: it should not
 * allocate.
 */
public interface ArrowPainter {
    /**
     * Draws an arrow from (x, y, z) to (x + dx, y + dy, z + dz), in drawing units.
     *
     * @param g the target
     * @param index the mass's index in the model
     * @param type its type
     * @param weight stroke weight, in pixels
     * @param argb colour, packed {@code 0xAARRGGBB}
     */
    void arrow(PGraphics g, int index, matModuleType type, float x, float y, float z, float dx, float dy, float dz,
               float weight, int argb);
}
