package tactus;

/**
 * Boundary conditions of a {@link TopoGenerator} block: which generated masses become fixed
 * points ({@link Ground3D}) after generation. The block's grid coordinates are (i, j, k) with
 * {@code 0 <= i < dimX}, {@code 0 <= j < dimY}, {@code 0 <= k < dimZ}.
 */
public enum Bound {
    /** Fixes the face {@code i = 0}. */
    X_LEFT,
    /** Fixes the face {@code i = dimX - 1}. */
    X_RIGHT,
    /** Fixes the face {@code j = 0}. */
    Y_LEFT,
    /** Fixes the face {@code j = dimY - 1}. */
    Y_RIGHT,
    /** Fixes the face {@code k = 0}. */
    Z_LEFT,
    /** Fixes the face {@code k = dimZ - 1}. */
    Z_RIGHT,
    /** Fixes the eight corners {@code (0 or dimX-1, 0 or dimY-1, 0 or dimZ-1)} (fewer when a dimension is 1). */
    FIXED_CORNERS,
    /** Fixes the centre mass {@code (dimX/2, dimY/2, dimZ/2)}, in integer division. */
    FIXED_CENTRE
}
