package tactus;


/** A spring and a damper in parallel: f = -K (d - l0) - Z (d(n) - d(n-1)) along the line between the masses. */
public final class SpringDamper3D extends ElasticInteraction {
    SpringDamper3D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
