package tactus;


/** A spring-damper along z only, on the signed difference z1 - z2. */
public final class SpringDamper1D extends ElasticInteraction {
    SpringDamper1D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
