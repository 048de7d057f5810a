package tactus.internal.model;

import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.linkModuleType;
import tactus.matModuleType;

/** Maps the engine's module kinds to the public module-type enums. */
public final class ModuleTypes {
    private ModuleTypes() {
    }

    public static matModuleType of(MassKind k) {
        switch (k) {
            case MASS3D:
                return matModuleType.Mass3D;
            case MASS3D_SIMPLE:
                return matModuleType.Mass3DSimple;
            case MASS2D_PLANE:
                return matModuleType.Mass2DPlane;
            case MASS1D:
                return matModuleType.Mass1D;
            case OSC3D:
                return matModuleType.Osc3D;
            case OSC1D:
                return matModuleType.Osc1D;
            case HAPTIC_INPUT3D:
                return matModuleType.HapticInput3D;
            case POS_INPUT3D:
                return matModuleType.PosInput3D;
            case GROUND3D:
                return matModuleType.Ground3D;
            case GROUND1D:
                return matModuleType.Ground1D;
            default:
                return matModuleType.UNDEFINED;
        }
    }

    public static linkModuleType of(LinkKind k) {
        switch (k) {
            case SPRING3D:
                return linkModuleType.Spring3D;
            case DAMPER3D:
                return linkModuleType.Damper3D;
            case SPRING_DAMPER3D:
                return linkModuleType.SpringDamper3D;
            case SPRING_DAMPER1D:
                return linkModuleType.SpringDamper1D;
            case ROPE3D:
                return linkModuleType.Rope3D;
            case CONTACT3D:
                return linkModuleType.Contact3D;
            case BUBBLE3D:
                return linkModuleType.Bubble3D;
            case PLANE_CONTACT3D:
                return linkModuleType.PlaneContact3D;
            case ATTRACTOR3D:
                return linkModuleType.Attractor3D;
            default:
                return linkModuleType.UNDEFINED;
        }
    }
}
