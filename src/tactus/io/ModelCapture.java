package tactus.io;

import tactus.Attractor3D;
import tactus.PhysicalModel;
import tactus.PlaneContact3D;
import tactus.Vect3D;

/**
 * Reads a whole model into a {@link ModelFile}, by index, under the model's lock. This is the one
 * place that knows which public calls give a module's type, ends and parameters.
 */
final class ModelCapture {
    private ModelCapture() {
    }

    static ModelFile of(PhysicalModel model) {
        return ModelLocks.locked(model, () -> read(model));
    }

    private static ModelFile read(PhysicalModel model) {
        ModelFile f = new ModelFile();
        f.gravity = model.getGravity();
        f.friction = model.getFriction();
        Vect3D d = model.getGravityDirection();
        f.dirX = d.x;
        f.dirY = d.y;
        f.dirZ = d.z;
        f.paramSystem = model.getParamSystem().name();
        f.simRate = model.getSimRate();
        for (int i = 0; i < model.getNumberOfMats(); i++) {
            f.masses.add(mass(model, i));
        }
        for (int i = 0; i < model.getNumberOfLinks(); i++) {
            f.links.add(link(model, i));
        }
        return f;
    }

    private static MassSpec mass(PhysicalModel model, int i) {
        MassSpec s = new MassSpec();
        s.type = FileTypes.massType(model, i);
        s.name = model.getMatNameAt(i);
        s.index = i;
        Vect3D p = model.getMatPosAt(i);
        s.x = p.x;
        s.y = p.y;
        s.z = p.z;
        if (FileTypes.isInertial(s.type)) {
            s.mass = model.getMatMassAt(i);
            Vect3D xr = model.getMatDelayedPosAt(i);
            double fs = model.getSimRate();
            s.vx = VelocityCodec.fromDelayed(p.x, xr.x, fs);
            s.vy = VelocityCodec.fromDelayed(p.y, xr.y, fs);
            s.vz = VelocityCodec.fromDelayed(p.z, xr.z, fs);
        }
        if (FileTypes.isOscillator(s.type)) {
            s.stiffness = model.getMatStiffnessAt(i);
            s.damping = model.getMatDampingAt(i);
        }
        return s;
    }

    private static LinkSpec link(PhysicalModel model, int i) {
        LinkSpec s = new LinkSpec();
        s.type = FileTypes.linkType(model, i);
        s.name = model.getLinkNameAt(i);
        s.index = i;
        s.m1 = model.getLinkMat1NameAt(i);
        String m2 = model.getLinkMat2NameAt(i);
        s.m2 = m2.isEmpty() ? s.m1 : m2;   // a plane contact's second end is the plane
        s.length = model.getLinkDRestAt(i);
        switch (s.type) {
            case "Attractor3D":
                s.attraction = ((Attractor3D) model.getInteractionAt(i)).getAttraction();
                break;
            case "PlaneContact3D":
                s.orientation = model.getPlaneOrientationAt(i);
                s.planePosition = model.getPlanePositionAt(i);
                s.stiffness = model.getLinkStiffnessAt(i);
                s.damping = model.getLinkDampingAt(i);
                break;
            default:
                s.stiffness = model.getLinkStiffnessAt(i);
                s.damping = model.getLinkDampingAt(i);
        }
        if (FileTypes.hasExtraParameters(s.type)) {
            String[] names = FileTypes.extraParameters(s.type);
            s.extra = new double[names.length];
            for (int k = 0; k < names.length; k++) {
                s.extra[k] = model.getInteractionAt(i).getExtraParameter(names[k]);
            }
        }
        return s;
    }
}
