package tactus;

import processing.core.PVector;

/**
 * A mutable 3D vector of doubles: positions, velocities and forces in the model's units.
 */
public final class Vect3D {
    /** The x component. */
    public double x;
    /** The y component. */
    public double y;
    /** The z component. */
    public double z;

    /** Creates the zero vector. */
    public Vect3D() {
    }

    /** Creates a vector from its components. */
    public Vect3D(double x, double y, double z) {
        this.x = x;
        this.y = y;
        this.z = z;
    }

    /** Creates a copy of another vector. */
    public Vect3D(Vect3D v) {
        this(v.x, v.y, v.z);
    }

    /** {@return the x component} */
    public double x() {
        return x;
    }

    /** {@return the y component} */
    public double y() {
        return y;
    }

    /** {@return the z component} */
    public double z() {
        return z;
    }

    /** Sets this vector to zero. */
    public void reset() {
        x = 0;
        y = 0;
        z = 0;
    }

    /** Sets the components and returns this vector. */
    public Vect3D set(double x, double y, double z) {
        this.x = x;
        this.y = y;
        this.z = z;
        return this;
    }

    /** Copies another vector into this one and returns this vector. */
    public Vect3D set(Vect3D v) {
        return set(v.x, v.y, v.z);
    }

    /** Adds another vector to this one and returns this vector. */
    public Vect3D add(Vect3D v) {
        return set(x + v.x, y + v.y, z + v.z);
    }

    /** Subtracts another vector from this one and returns this vector. */
    public Vect3D sub(Vect3D v) {
        return set(x - v.x, y - v.y, z - v.z);
    }

    /** Multiplies this vector by a scalar and returns it. */
    public Vect3D mult(double s) {
        return set(x * s, y * s, z * s);
    }

    /** Divides this vector by a scalar and returns it. */
    public Vect3D div(double s) {
        return set(x / s, y / s, z / s);
    }

    /** {@return the Euclidean length of this vector} */
    public double norm() {
        return Math.sqrt(x * x + y * y + z * z);
    }

    /** {@return the squared length of this vector} */
    public double sqNorm() {
        return x * x + y * y + z * z;
    }

    /** {@return the distance between this point and another} */
    public double dist(Vect3D v) {
        double dx = x - v.x, dy = y - v.y, dz = z - v.z;
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** {@return the squared distance between this point and another} */
    public double sqDist(Vect3D v) {
        double dx = x - v.x, dy = y - v.y, dz = z - v.z;
        return dx * dx + dy * dy + dz * dz;
    }

    /**
     * Compares the components exactly, as the paper's engine does. This overloads {@code equals}; it does not
     * override {@link Object#equals(Object)}, so collections still compare vectors by identity.
     *
     * @param v the other vector (null gives false)
     * @return true if x, y and z are equal
     */
    public boolean equals(Vect3D v) {
        return v != null && x == v.x && y == v.y && z == v.z;
    }

    /** {@return true when all three components are finite} */
    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }

    /** {@return a new Processing {@code PVector} with this vector's components as floats} */
    public PVector toPVector() {
        tactus.internal.model.OptionalLibrary.PROCESSING_CORE.require("a PVector call (toPVector, getMatPVector, "
                + "getMatForcePVector)", "without Processing core read the same values as a Vect3D: getMatPosition(name), "
                + "getMatForce(name), and their fields x, y, z");
        return new PVector((float) x, (float) y, (float) z);
    }

    @Override
    public String toString() {
        return "(" + x + ", " + y + ", " + z + ")";
    }
}
