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
            // MERGE: where the model has getMatDelayedPosAt(i), use VelocityCodec.fromDelayed(p.x, xr.x, fs), ...
            // with xr = model.getMatDelayedPosAt(i): exact by construction instead of recovered.
            Vect3D v = model.getMatVelAt(i);
            double fs = model.getSimRate();
            s.vx = VelocityCodec.encode(p.x, v.x, fs);
            s.vy = VelocityCodec.encode(p.y, v.y, fs);
            s.vz = VelocityCodec.encode(p.z, v.z, fs);
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
        // MERGE: by name until the model offers the ends by index; once interaction names can repeat this
        // must become getLinkMat1NameAt(i) / getLinkMat2NameAt(i) (and the plane and attractor getters below
        // getPlaneOrientationAt(i) / getPlanePositionAt(i) and an attraction getter by index), or a repeated
        // name would save the first link's ends and parameters for every link of that name.
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
