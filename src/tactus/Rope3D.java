package tactus;


/** A spring-damper that acts only while the masses are farther apart than its length. */
public final class Rope3D extends ElasticInteraction {
    Rope3D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
