package tactus.export;

import java.util.HashMap;
import java.util.Map;

import tactus.Attractor3D;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.linkModuleType;
import tactus.matModuleType;
import tactus.paramSystem;

/**
 * A model as the exporter sees it: every mass and interaction with its parameters converted to per-step values
 * (the numbers the engine uses at each step), read through the public facade. Refuses what cannot export.
 */
final class Scene {
    /** One mass. Positions are in length units; forces, stiffness and damping per step. */
    static final class MassRow {
        String name;
        matModuleType type;
        double m;
        final double[] x0 = new double[3];
        final double[] xr0 = new double[3];
        final double[] f0 = new double[3];
        final double[] rest = new double[3];
        double k;
        double z;
    }

    /** One interaction; {@code b} is -1 for a plane contact. Values per step. */
    static final class LinkRow {
        String name;
        linkModuleType type;
        int a;
        int b = -1;
        double k;
        double z;
        double l0;
        double attraction;
        int axis = -1;
        double planePos;
        /** The parameters beyond K, Z and the length of a nonlinear kind, per step, in its descriptor's order. */
        double[] extra = new double[0];
    }

    final int fs;
    final boolean real;
    final double friction;
    final double[] g = new double[3];
    final MassRow[] masses;
    final LinkRow[] links;
    private final Map<String, Integer> massIndex = new HashMap<>();
    private final Map<String, Integer> linkIndex = new HashMap<>();

    private Scene(PhysicalModel model) {
        fs = model.getSimRate();
        real = model.getParamSystem() == paramSystem.REAL_UNITS;
        friction = real ? model.getFriction() / fs : model.getFriction();
        double gm = model.getGravity();
        if (gm != 0) {
            Vect3D up = model.getGravityDirection();
            double n = Math.sqrt(up.x * up.x + up.y * up.y + up.z * up.z);
            double gs = real ? gm / ((double) fs * fs) : gm;
            g[0] = -gs * up.x / n;
            g[1] = -gs * up.y / n;
            g[2] = -gs * up.z / n;
        }
        String[] groups = model.getContactGroupSubsets();
        if (groups.length > 0) {
            throw new FaustExportException("contact group of subset \"" + groups[0] + "\"",
                    "contact groups find their pairs at run time (a neighbour list), which a Faust signal graph "
                            + "cannot; add Contact3D links for the pairs that can touch instead");
        }
        masses = new MassRow[model.getNumberOfMats()];
        for (int i = 0; i < masses.length; i++) {
            masses[i] = readMass(model, i);
            massIndex.put(masses[i].name, i);
        }
        links = new LinkRow[model.getNumberOfLinks()];
        for (int i = 0; i < links.length; i++) {
            links[i] = readLink(model, i);
            linkIndex.put(links[i].name, i);
        }
    }

    /** Reads a model; throws {@link FaustExportException} naming the first module that cannot export. */
    static Scene read(PhysicalModel model) {
        return new Scene(model);
    }

    /** @return the index of a mass, or -1 */
    int mass(String name) {
        Integer i = massIndex.get(name);
        return i == null ? -1 : i;
    }

    /** @return the index of an interaction, or -1 (the first of that name) */
    int link(String name) {
        Integer i = linkIndex.get(name);
        return i == null ? -1 : i;
    }

    double stiffnessIn(double k) {
        return real ? k / ((double) fs * fs) : k;
    }

    double dampingIn(double z) {
        return real ? z / fs : z;
    }

    /** @return the factor that turns a force in the model's units into a per-step force */
    double forceScale() {
        return real ? 1.0 / ((double) fs * fs) : 1.0;
    }

    private MassRow readMass(PhysicalModel model, int i) {
        MassRow r = new MassRow();
        r.name = model.getMatNameAt(i);
        r.type = model.getMatTypeAt(i);
        switch (r.type) {
            case HapticInput3D:
                throw new FaustExportException(r.type + " \"" + r.name + "\"", "the haptic avatar follows a device "
                        + "and accumulates forces for it; give the exported program a force input instead");
            case PosInput3D:
                throw new FaustExportException(r.type + " \"" + r.name + "\"", "a position driver follows targets "
                        + "set from the sketch, which the exported program has no way to receive");
            case UNDEFINED:
                throw new FaustExportException("mass \"" + r.name + "\"", "it is under velocity control; call "
                        + "stopVelocityControl first");
            default:
                break;
        }
        if (model.isVelocityControlled(r.name)) {
            throw new FaustExportException("mass \"" + r.name + "\"", "it is under velocity control; call "
                    + "stopVelocityControl first");
        }
        copy(model.getMatPosAt(i), r.x0);
        copy(model.getMatDelayedPosAt(i), r.xr0);
        copy(model.getMatFrcAt(i), r.f0);
        for (int a = 0; a < 3; a++) {
            r.f0[a] *= forceScale();
        }
        boolean fixed = r.type == matModuleType.Ground3D || r.type == matModuleType.Ground1D;
        r.m = fixed ? 0 : model.getMatMassAt(i);
        if (r.type == matModuleType.Osc3D || r.type == matModuleType.Osc1D) {
            r.k = stiffnessIn(model.getMatStiffnessAt(i));
            r.z = dampingIn(model.getMatDampingAt(i));
            copy(model.getOscRestPosition(r.name), r.rest);
        }
        return r;
    }

    private LinkRow readLink(PhysicalModel model, int i) {
        LinkRow r = new LinkRow();
        r.name = model.getLinkNameAt(i);
        r.type = model.getLinkTypeAt(i);
        r.a = model.getLinkMat1IdxAt(i);
        if (r.type.isNonlinear()) {
            // the kind's descriptor names its parameters and how each converts to a per-step value
            r.b = model.getLinkMat2IdxAt(i);
            r.k = stiffnessIn(model.getLinkStiffnessAt(i));
            r.z = dampingIn(model.getLinkDampingAt(i));
            r.l0 = model.getLinkDRestAt(i);
            String[] names = r.type.extraParameterNames();
            r.extra = new double[names.length];
            for (int k = 0; k < names.length; k++) {
                double v = model.getInteractionAt(i).getExtraParameter(names[k]);
                int power = r.type.extraParameterRatePower(k);
                r.extra[k] = !real || power == 0 ? v : power == 1 ? v / fs : v / ((double) fs * fs);
            }
            return r;
        }
        switch (r.type) {
            case PlaneContact3D:
                r.k = stiffnessIn(model.getLinkStiffnessAt(i));
                r.z = dampingIn(model.getLinkDampingAt(i));
                r.l0 = model.getLinkDRestAt(i);
                r.axis = model.getPlaneOrientationAt(i);
                r.planePos = model.getPlanePositionAt(i);
                return r;
            case Attractor3D:
                r.b = model.getLinkMat2IdxAt(i);
                r.l0 = model.getLinkDRestAt(i);
                r.attraction = model.getInteractionAt(i) instanceof Attractor3D
                        ? ((Attractor3D) model.getInteractionAt(i)).getAttraction() * forceScale() : 0;
                return r;
            case Damper3D:
                r.b = model.getLinkMat2IdxAt(i);
                r.z = dampingIn(model.getLinkDampingAt(i));
                return r;
            case Spring3D:
                r.b = model.getLinkMat2IdxAt(i);
                r.k = stiffnessIn(model.getLinkStiffnessAt(i));
                r.l0 = model.getLinkDRestAt(i);
                return r;
            case SpringDamper3D:
            case SpringDamper1D:
            case Rope3D:
            case Contact3D:
            case Bubble3D:
                r.b = model.getLinkMat2IdxAt(i);
                r.k = stiffnessIn(model.getLinkStiffnessAt(i));
                r.z = dampingIn(model.getLinkDampingAt(i));
                r.l0 = model.getLinkDRestAt(i);
                return r;
            default:
                throw new FaustExportException("interaction \"" + r.name + "\"", "its type " + r.type
                        + " has no Faust form");
        }
    }

    private static void copy(Vect3D v, double[] out) {
        out[0] = v.x;
        out[1] = v.y;
        out[2] = v.z;
    }
}
