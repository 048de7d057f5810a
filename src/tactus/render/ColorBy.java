package tactus.render;

/**
 * What the {@link ModelDrawer} colours elements by. With anything but {@link #TYPE}, the colour comes from the
 * drawer's {@link ColorScale} and only its alpha from the element's style (a hidden type stays hidden).
 */
public enum ColorBy {
    /** Each element in the colour of its type's style (with the per-type strain gradient of links). */
    TYPE,
    /**
     * Moving masses by their speed (length units per second), links by the mean speed of their two masses.
     * Fixed points, avatars and position drivers keep their type colour.
     */
    SPEED,
    /**
     * Moving masses by the norm of the force of the interactions on them (the model's force unit), links by
     * the mean of their two masses' forces. Fixed points, avatars and position drivers keep their type colour.
     */
    FORCE,
    /**
     * Links by their strain, elongation over length parameter (dimensionless, negative when compressed; see
     * {@link LinkStyle#strain(double, double)}); masses keep their type colour.
     */
    STRAIN
}
