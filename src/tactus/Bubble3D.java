package tactus;


/** Keeps the first mass within a radius (its length) of the second: a spring-damper that acts only outside it. */
public final class Bubble3D extends ElasticInteraction {
    Bubble3D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
