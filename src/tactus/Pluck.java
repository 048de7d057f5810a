package tactus;

/**
 * A plucking interaction, Faust mi.lib's {@code nlPluck}: a repulsive spring-damper on the elongation e that pushes
 * back harder up to a tenth of its distance scale, then less, and lets go (no force) once |e| reaches the scale.
 */
public abstract class Pluck extends ElasticInteraction {
    Pluck(ModuleHandles handles, int id) {
        super(handles, id);
    }

    /** {@return the distance scale past which the pluck lets go (model length units; mi.lib's scale)} */
    public double getScale() {
        return aux("getScale", 0);
    }

    /** Sets the distance scale past which the pluck lets go, &gt; 0 (model length units; mi.lib's scale). */
    public void setScale(double scale) {
        aux("setScale", 0, scale);
    }
}
