package tactus.render;

import processing.core.PGraphics;
import tactus.linkModuleType;

/**
 * Draws one interaction. Replace the {@link ModelDrawer}'s painter to draw links your own way; the drawer has
 * already applied the view to the end points, chosen the colour (strain gradient included) and skipped fully
 * transparent links. Called on the drawing thread, between {@link #begin} and {@link #end}, once per visible link
 * per frame: it should not allocate.
 */
public interface LinkPainter {
    /**
     * Called once per frame before the first link, inside the drawer's {@code pushStyle()}.
     *
     * @param g the target
     * @param count the number of interactions in the frame
     */
    default void begin(PGraphics g, int count) {
    }

    /**
     * Draws interaction {@code index} from (x1, y1, z1) to (x2, y2, z2), in drawing units. For a plane contact the
     * second end is the foot of the mass on the plane.
     *
     * @param g the target
     * @param index the interaction's index in the model
     * @param type its type
     * @param weight stroke weight, in pixels
     * @param argb stroke colour, packed {@code 0xAARRGGBB}
     */
    void link(PGraphics g, int index, linkModuleType type, float x1, float y1, float z1, float x2, float y2, float z2,
              float weight, int argb);

    /** Called once per frame after the last link. */
    default void end(PGraphics g) {
    }
}
