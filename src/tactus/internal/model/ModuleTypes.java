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

    /** @return the public type of a kind: the constant of {@link linkModuleType} named by its label. */
    public static linkModuleType of(LinkKind k) {
        return linkModuleType.valueOf(k.label());
    }
}
