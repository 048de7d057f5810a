package tactus.io;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import tactus.PhysicalModel;
import tactus.StabilityPolicy;
import tactus.Vect3D;
import tactus.linkModuleType;

/**
 * Adds the content of a {@link ModelFile} to a model, all or nothing: it checks names and
 * references against the model, builds the file into a scratch model of the same rate and units
 * (which runs every parameter check of the model), and only then builds it into the target, undoing
 * its additions if the target still refuses one.
 */
final class ModelApplier {
    private final String source;

    ModelApplier(String source) {
        this.source = source;
    }

    void apply(ModelFile f, PhysicalModel target) {
        ModelLocks.locked(target, () -> {
            checkUnits(f, target);
            Set<String> outside = checkNames(f, target);
            PhysicalModel scratch = new PhysicalModel(target.getSimRate(), target.getDisplayRate(),
                    target.getParamSystem());
            scratch.setStabilityPolicy(StabilityPolicy.OFF);
            for (String n : outside) {
                scratch.addGround3D(n, target.getMatPosition(n));
            }
            new Build(f, scratch, true).run();
            new Build(f, target, false).runOrUndo();
            return null;
        });
    }

    private void checkUnits(ModelFile f, PhysicalModel target) {
        if (f.paramSystem != null && !f.paramSystem.equals(target.getParamSystem().name())) {
            throw new ModelFileException(source, f.unitsLine, "units", "the file was written in " + f.paramSystem
                    + " but the model uses " + target.getParamSystem().name()
                    + "; load it into a model created with paramSystem." + f.paramSystem, null);
        }
    }

    /** @return the masses the file's links refer to that live in the target model, not in the file. */
    private Set<String> checkNames(ModelFile f, PhysicalModel target) {
        Set<String> inFile = new HashSet<>();
        for (MassSpec m : f.masses) {
            if (target.matExists(m.name)) {
                throw new ModelFileException(source, m.line, m.element, "the model already has a mass named \""
                        + m.name + "\"", null);
            }
            inFile.add(m.name);
        }
        Set<String> outside = new HashSet<>();
        for (LinkSpec l : f.links) {
            for (String end : new String[] {l.m1, l.m2}) {
                if (!inFile.contains(end)) {
                    if (!target.matExists(end)) {
                        throw new ModelFileException(source, l.line, l.element, "interaction \"" + l.name
                                + "\" refers to mass \"" + end + "\", which is neither in the file nor in the model", null);
                    }
                    outside.add(end);
                }
            }
        }
        return outside;
    }

    /** One pass of adding a file's content to one model. */
    private final class Build {
        private final ModelFile f;
        private final PhysicalModel m;
        private final List<String> addedMasses = new ArrayList<>();
        private int linksBefore;
        private double gravity;
        private double friction;
        private Vect3D direction;
        /** The scratch pass runs without gravity (the target checks it), so that notes are printed once, for the target. */
        private final boolean scratch;

        Build(ModelFile f, PhysicalModel m, boolean scratch) {
            this.f = f;
            this.m = m;
            this.scratch = scratch;
        }

        void runOrUndo() {
            gravity = m.getGravity();
            friction = m.getFriction();
            direction = m.getGravityDirection();
            linksBefore = m.getNumberOfLinks();
            try {
                run();
                m.init();
            } catch (RuntimeException e) {
                undo();
                throw e;
            }
        }

        void run() {
            setGlobals();
            for (MassSpec s : f.masses) {
                try {
                    addMass(s);
                } catch (ModelFileException e) {
                    throw e;
                } catch (RuntimeException e) {
                    throw new ModelFileException(source, s.line, s.element, e.getMessage(), e);
                }
                addedMasses.add(s.name);
            }
            for (LinkSpec s : f.links) {
                try {
                    addLink(s);
                } catch (RuntimeException e) {
                    throw new ModelFileException(source, s.line, s.element, e.getMessage(), e);
                }
            }
        }

        private void setGlobals() {
            try {
                m.setGravity(scratch ? 0 : f.gravity);
                m.setFriction(f.friction);
                Vect3D d = m.getGravityDirection();
                if (d.x != f.dirX || d.y != f.dirY || d.z != f.dirZ) {
                    m.setGravityDirection(new Vect3D(f.dirX, f.dirY, f.dirZ));
                }
            } catch (RuntimeException e) {
                throw new ModelFileException(source, f.globalLine, "global", e.getMessage(), e);
            }
        }

        private void addMass(MassSpec s) {
            Vect3D p = new Vect3D(s.x, s.y, s.z);
            Vect3D v = new Vect3D(s.vx, s.vy, s.vz);
            switch (s.type) {
                case "Ground1D":
                    m.addGround1D(s.name, p);
                    break;
                case "Ground3D":
                    m.addGround3D(s.name, p);
                    break;
                case "HapticInput3D":
                    m.addHapticInput3D(s.name, p, s.smoothing);
                    break;
                case "PosInput3D":
                    m.addPosInput3D(s.name, p, s.smoothing);
                    break;
                case "Mass1D":
                    m.addMass1D(s.name, s.mass, p, v);
                    break;
                case "Mass2DPlane":
                    m.addMass2DPlane(s.name, s.mass, p, v);
                    break;
                case "Mass3D":
                    m.addMass3D(s.name, s.mass, p, v);
                    break;
                case "Osc1D":
                    m.addOsc1D(s.name, s.mass, s.stiffness, s.damping, p, v);
                    break;
                case "Osc3D":
                    m.addOsc3D(s.name, s.mass, s.stiffness, s.damping, p, v);
                    break;
                case "Mass3DSimple":
                    m.addMass3DSimple(s.name, s.mass, p, v);
                    break;
                default:
                    throw new IllegalStateException("unhandled mass type " + s.type);
            }
        }

        private void addLink(LinkSpec s) {
            if (FileTypes.hasExtraParameters(s.type)) {
                m.addInteraction(linkModuleType.valueOf(s.type), s.name, s.length, s.stiffness, s.damping, s.extra,
                        s.m1, s.m2);
                return;
            }
            switch (s.type) {
                case "Spring3D":
                    m.addSpring3D(s.name, s.length, s.stiffness, s.m1, s.m2);
                    break;
                case "Damper3D":
                    m.addDamper3D(s.name, s.damping, s.m1, s.m2);
                    break;
                case "SpringDamper3D":
                    m.addSpringDamper3D(s.name, s.length, s.stiffness, s.damping, s.m1, s.m2);
                    break;
                case "SpringDamper1D":
                    m.addSpringDamper1D(s.name, s.length, s.stiffness, s.damping, s.m1, s.m2);
                    break;
                case "Rope3D":
                    m.addRope3D(s.name, s.length, s.stiffness, s.damping, s.m1, s.m2);
                    break;
                case "Contact3D":
                    m.addContact3D(s.name, s.length, s.stiffness, s.damping, s.m1, s.m2);
                    break;
                case "Bubble3D":
                    m.addBubble3D(s.name, s.length, s.stiffness, s.damping, s.m1, s.m2);
                    break;
                case "PlaneContact3D":
                    m.addPlaneContact(s.name, s.length, s.stiffness, s.damping, s.orientation, s.planePosition, s.m1);
                    break;
                case "Attractor3D":
                    m.addAttractor3D(s.name, s.length, s.attraction, s.m1, s.m2);
                    break;
                default:
                    throw new IllegalStateException("unhandled interaction type " + s.type);
            }
        }

        private void undo() {
            while (m.getNumberOfLinks() > linksBefore) {
                m.removeLink(m.getNumberOfLinks() - 1);
            }
            for (int i = addedMasses.size() - 1; i >= 0; i--) {
                m.removeMatAndConnectedLinks(addedMasses.get(i));
            }
            m.setGravity(gravity);
            m.setFriction(friction);
            Vect3D d = m.getGravityDirection();
            if (d.x != direction.x || d.y != direction.y || d.z != direction.z) {
                m.setGravityDirection(direction);
            }
        }
    }
}
