package tactus.engine;

/**
 * The global medium shared by every mass: gravity as an acceleration vector and viscous air
 * friction, both in per-step units. Masses accelerate along the gravity vector, so a
 * vector (0, 0, -g) makes them fall toward -z.
 */
final class Medium {
    double gx;
    double gy;
    double gz;
    double friction;

    boolean hasGravity() {
        return gx != 0 || gy != 0 || gz != 0;
    }

    boolean hasFriction() {
        return friction != 0;
    }
}
