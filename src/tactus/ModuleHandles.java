package tactus;

import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.internal.ModelCore;
import tactus.internal.model.HandleFactory;
import tactus.internal.realtime.ModelLock;

/** Makes and retires the handles of one model's modules, for its directory (see {@link HandleFactory}). */
final class ModuleHandles implements HandleFactory {
    /** Set once by the model, before its first module is added. */
    ModelCore core;
    ModelLock gate;

    @Override
    public Object newMass(int id, MassKind kind) {
        return mass(id, kind);
    }

    @Override
    public Object newLink(int id, LinkKind kind) {
        return link(id, kind);
    }

    @Override
    public void retire(Object handle) {
        ((Module) handle).invalidate();
    }

    private Mass mass(int id, MassKind kind) {
        switch (kind) {
            case MASS3D:
                return new Mass3D(core, gate, id);
            case MASS3D_SIMPLE:
                return new Mass3DSimple(core, gate, id);
            case MASS2D_PLANE:
                return new Mass2DPlane(core, gate, id);
            case MASS1D:
                return new Mass1D(core, gate, id);
            case OSC3D:
                return new Osc3D(core, gate, id);
            case OSC1D:
                return new Osc1D(core, gate, id);
            case HAPTIC_INPUT3D:
                return new HapticInput3D(core, gate, id);
            case POS_INPUT3D:
                return new PosInput3D(core, gate, id);
            case GROUND3D:
                return new Ground3D(core, gate, id);
            case GROUND1D:
                return new Ground1D(core, gate, id);
            default:
                throw new IllegalStateException("no handle for " + kind);
        }
    }

    private Interaction link(int id, LinkKind kind) {
        switch (kind) {
            case SPRING3D:
                return new Spring3D(core, gate, id);
            case DAMPER3D:
                return new Damper3D(core, gate, id);
            case SPRING_DAMPER3D:
                return new SpringDamper3D(core, gate, id);
            case SPRING_DAMPER1D:
                return new SpringDamper1D(core, gate, id);
            case ROPE3D:
                return new Rope3D(core, gate, id);
            case CONTACT3D:
                return new Contact3D(core, gate, id);
            case BUBBLE3D:
                return new Bubble3D(core, gate, id);
            case PLANE_CONTACT3D:
                return new PlaneContact3D(core, gate, id);
            case ATTRACTOR3D:
                return new Attractor3D(core, gate, id);
            case QUADRATIC_SPRING_DAMPER3D:
                return new QuadraticSpringDamper3D(core, gate, id);
            case QUADRATIC_SPRING_DAMPER1D:
                return new QuadraticSpringDamper1D(core, gate, id);
            case CUBIC_SPRING_DAMPER3D:
                return new CubicSpringDamper3D(core, gate, id);
            case CUBIC_SPRING_DAMPER1D:
                return new CubicSpringDamper1D(core, gate, id);
            case CLIPPED_SPRING_DAMPER3D:
                return new ClippedSpringDamper3D(core, gate, id);
            case CLIPPED_SPRING_DAMPER1D:
                return new ClippedSpringDamper1D(core, gate, id);
            case PLUCK3D:
                return new Pluck3D(core, gate, id);
            case PLUCK1D:
                return new Pluck1D(core, gate, id);
            case BOW3D:
                return new Bow3D(core, gate, id);
            case BOW1D:
                return new Bow1D(core, gate, id);
            case CLIPPED_CONTACT3D:
                return new ClippedContact3D(core, gate, id);
            case CLIPPED_CONTACT1D:
                return new ClippedContact1D(core, gate, id);
            default:
                throw new IllegalStateException("no handle for " + kind);
        }
    }
}
