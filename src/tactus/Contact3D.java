package tactus;


/** A spring-damper that acts only while the masses are closer than its threshold (its length). */
public final class Contact3D extends ElasticInteraction {
    Contact3D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
