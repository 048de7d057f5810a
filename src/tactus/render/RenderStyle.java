package tactus.render;

import tactus.linkModuleType;
import tactus.matModuleType;

/**
 * The styles of every mass type and every interaction type, with the paper's engine's defaults: brown Mass3D,
 * green fixed points, Mass2DPlane and Osc3D, red haptic avatar (radius 10); the types it could not style
 * (Mass1D, Ground1D, Osc1D, Mass3DSimple, PosInput3D) in grey at radius 5, as it drew them. Links are 2 pixels
 * wide, without strain gradient (strain max 2, transparent strain colour); contacts, bubbles, plane contacts and
 * attractors are hidden (alpha 0) until given a colour. {@code UNDEFINED} has a hidden style of its own so that
 * drawing never fails, but it is never returned for a live module.
 */
public final class RenderStyle {
    private final MassStyle[] masses = new MassStyle[matModuleType.values().length];
    private final LinkStyle[] links = new LinkStyle[linkModuleType.values().length];

    /** Creates the default styles. */
    public RenderStyle() {
        for (matModuleType t : matModuleType.values()) {
            masses[t.ordinal()] = defaultMass(t);
        }
        for (linkModuleType t : linkModuleType.values()) {
            links[t.ordinal()] = defaultLink(t);
        }
    }

    /** {@return the (mutable) style of a mass type} */
    public MassStyle mass(matModuleType type) {
        if (type == null) {
            throw new IllegalArgumentException("RenderStyle.mass: the mass type must not be null");
        }
        return masses[type.ordinal()];
    }

    /** {@return the (mutable) style of an interaction type} */
    public LinkStyle link(linkModuleType type) {
        if (type == null) {
            throw new IllegalArgumentException("RenderStyle.link: the link type must not be null");
        }
        return links[type.ordinal()];
    }

    /** {@return the default style of a mass type, as a new object} */
    public static MassStyle defaultMass(matModuleType type) {
        switch (type) {
            case Mass3D:
                return new MassStyle(180, 100, 0, 10);
            case Ground3D:
            case Mass2DPlane:
            case Osc3D:
                return new MassStyle(0, 220, 130, 10);
            case HapticInput3D:
                return new MassStyle(255, 50, 50, 10);
            case UNDEFINED: {
                MassStyle s = new MassStyle(125, 125, 125, 5);
                s.setColor(125, 125, 125, 0);
                return s;
            }
            default:
                return new MassStyle(125, 125, 125, 5);
        }
    }

    /** {@return the default style of an interaction type, as a new object} */
    public static LinkStyle defaultLink(linkModuleType type) {
        int c = type.defaultColor(); // the kind's descriptor: 0xAARRGGBB, alpha 0 for the kinds drawn without a line
        return new LinkStyle((c >> 16) & 0xFF, (c >> 8) & 0xFF, c & 0xFF, (c >>> 24) & 0xFF, 2);
    }
}
