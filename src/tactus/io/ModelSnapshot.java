package tactus.io;

import tactus.Attractor3D;
import tactus.PhysicalModel;
import tactus.PlaneContact3D;
import tactus.Vect3D;

/**
 * Reads a whole model into a {@link ModelFile}, by index, under the model's lock. This is the one
 * place that knows which public calls give a module's type, ends and parameters.
 */
final class ModelSnapshot {
    private ModelSnapshot() {
    }

    static ModelFile of(PhysicalModel model) {
        ModelFile f = new ModelFile();
        synchronized (model.getLock()) {
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
        }
        return f;
    }

    private static MassSpec mass(PhysicalModel model, int i) {
        MassSpec s = new MassSpec();
        s.type = ModuleTypes.massType(model, i);
        s.name = model.getMatNameAt(i);
        s.index = i;
        Vect3D p = model.getMatPosAt(i);
        s.x = p.x;
        s.y = p.y;
        s.z = p.z;
        if (ModuleTypes.isInertial(s.type)) {
            s.mass = model.getMatMassAt(i);
            Vect3D v = model.getMatVelAt(i);
            double fs = model.getSimRate();
            s.vx = VelocityCodec.encode(p.x, v.x, fs);
            s.vy = VelocityCodec.encode(p.y, v.y, fs);
            s.vz = VelocityCodec.encode(p.z, v.z, fs);
        }
        if (ModuleTypes.isOscillator(s.type)) {
            s.stiffness = model.getMatStiffnessAt(i);
            s.damping = model.getMatDampingAt(i);
        }
        return s;
    }

    private static LinkSpec link(PhysicalModel model, int i) {
        LinkSpec s = new LinkSpec();
        s.type = ModuleTypes.linkType(model, i);
        s.name = model.getLinkNameAt(i);
        s.index = i;
        // By name until the model offers the ends by index (getLinkMat1NameAt / getLinkMat2NameAt).
        String[] ends = model.getLinkMatNames(s.name);
        s.m1 = ends[0];
        s.m2 = ends[1];
        s.length = model.getLinkDRestAt(i);
        switch (s.type) {
            case "Attractor3D":
                s.attraction = ((Attractor3D) model.getInteraction(s.name)).getAttraction();
                break;
            case "PlaneContact3D":
                PlaneContact3D p = (PlaneContact3D) model.getInteraction(s.name);
                s.orientation = p.getOrientation();
                s.planePosition = p.getPlanePosition();
                s.stiffness = model.getLinkStiffnessAt(i);
                s.damping = model.getLinkDampingAt(i);
                break;
            default:
                s.stiffness = model.getLinkStiffnessAt(i);
                s.damping = model.getLinkDampingAt(i);
        }
        return s;
    }
}
