package tactus;

/** A clipped cubic contact that pushes two masses apart while they are closer than its threshold, on the penetration threshold - d (mi.lib's nlCollisionClipped in 3-D). */
public final class ClippedContact3D extends ClippedInteraction {
    ClippedContact3D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
