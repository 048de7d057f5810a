package tactus;

/**
 * The type of a mass-type module, as returned by {@link PhysicalModel#getMatTypeAt(int)}. The lower-case name and
 * the constants keep drawing code written for the paper's engine ({@code switch (mdl.getMatTypeAt(i)) { case
 * Mass3D: ... }}) source-compatible. {@code PosInput3D} is a Tactus addition.
 */
public enum matModuleType {
    /** A free 3D mass. */
    Mass3D,
    /** A mass that moves along z only. */
    Mass1D,
    /** A mass that moves in its initial z plane only. */
    Mass2DPlane,
    /** A fixed point in 3D. */
    Ground3D,
    /** A fixed point for 1D models. */
    Ground1D,
    /** A free 3D mass that ignores gravity and air friction. */
    Mass3DSimple,
    /** A 3D oscillator: a mass tied to its rest point by an internal spring and damper. */
    Osc3D,
    /** A 1D oscillator (along z). */
    Osc1D,
    /** The haptic avatar, driven by the device position. */
    HapticInput3D,
    /** A kinematic position driver that reports no force (a Tactus addition). */
    PosInput3D,
    /** No module of a known type (never returned for a live module). */
    UNDEFINED
}
