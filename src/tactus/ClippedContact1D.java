package tactus;

/** A clipped cubic contact along z, mass 2 above mass 1: it acts while z2 - z1 is below its threshold, on the penetration z1 + threshold - z2 (mi.lib's nlCollisionClipped). */
public final class ClippedContact1D extends ClippedInteraction {
    ClippedContact1D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
