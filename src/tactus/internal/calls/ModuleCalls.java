package tactus.internal.calls;

import tactus.Vect3D;
import tactus.internal.ModelCore;
import tactus.internal.realtime.ModelLock;

/**
 * The calls of the module handles, by module id: each enters the model once, as the facade's calls do (a setter
 * through {@link ModelLock#enterChange()}, so that while another thread steps the model it is queued and returns at
 * once; a read through {@link ModelLock#enter()}), checks that the module is still the one the handle was made for,
 * and hands the work to the room that does it. A mass is named by its id and its stamp ({@code
 * Directory.massStamp}): a mass made fixed keeps its id under a new stamp. Not API.
 */
public final class ModuleCalls extends Calls {
    public ModuleCalls(ModelCore core, ModelLock gate) {
        super(core, gate);
    }

    private void mass(int id, int stamp) {
        core.dir.checkMass(id, stamp);
    }

    private void link(int id) {
        core.dir.checkLink(id);
    }

    // ---------------------------------------------------------------- masses

    public String massName(int id, int stamp) {
        enter();
        try {
            mass(id, stamp);
            return core.dir.massName(id);
        } finally {
            exit();
        }
    }

    public String massType(int id, int stamp) {
        enter();
        try {
            mass(id, stamp);
            return core.dir.massKind(id).label();
        } finally {
            exit();
        }
    }

    /** What a mass read returns: its position, velocity or force. */
    public enum Motion { POSITION, VELOCITY, FORCE }

    public Vect3D motion(int id, int stamp, Motion what, Vect3D out) {
        enter();
        try {
            mass(id, stamp);
            switch (what) {
                case POSITION:
                    return core.state.position(id, out);
                case VELOCITY:
                    return core.state.velocity(id, out);
                default:
                    return core.state.force(id, out);
            }
        } finally {
            exit();
        }
    }

    public void setPosition(int id, int stamp, Vect3D pos) {
        enterChange();
        try {
            mass(id, stamp);
            core.state.setPosition(id, pos);
        } finally {
            exit();
        }
    }

    public void setVelocity(int id, int stamp, Vect3D vel) {
        enterChange();
        try {
            mass(id, stamp);
            core.state.setVelocity("setVelocity", id, vel);
        } finally {
            exit();
        }
    }

    public void applyForce(int id, int stamp, double fx, double fy, double fz) {
        enterChange();
        try {
            mass(id, stamp);
            core.state.addImpulse(id, fx, fy, fz);
        } finally {
            exit();
        }
    }

    public void setInputTarget(int id, int stamp, Vect3D pos) {
        enterChange();
        try {
            mass(id, stamp);
            core.state.setInputTarget(id, pos.x, pos.y, pos.z);
        } finally {
            exit();
        }
    }

    public Vect3D takeAvatarForce(int id, int stamp, Vect3D out) {
        enter();
        try {
            mass(id, stamp);
            return core.state.takeAvatarForce(id, out);
        } finally {
            exit();
        }
    }

    /** A parameter of a mass: its inertia, or an oscillator's stiffness or damping. */
    public enum MassParam { MASS, STIFFNESS, DAMPING }

    public double massParam(int id, int stamp, MassParam p) {
        enter();
        try {
            mass(id, stamp);
            switch (p) {
                case MASS:
                    return core.params.mass("getMass", id);
                case STIFFNESS:
                    return core.params.oscStiffness("getStiffness", id);
                default:
                    return core.params.oscDamping("getDamping", id);
            }
        } finally {
            exit();
        }
    }

    public void setMassParam(int id, int stamp, MassParam p, double v) {
        enterChange();
        try {
            mass(id, stamp);
            switch (p) {
                case MASS:
                    core.params.setMass("setMass", id, v);
                    break;
                case STIFFNESS:
                    core.params.setOsc("setStiffness", id, v, Double.NaN);
                    break;
                default:
                    core.params.setOsc("setDamping", id, Double.NaN, v);
                    break;
            }
        } finally {
            exit();
        }
    }

    // ---------------------------------------------------------------- interactions

    public String linkName(int id) {
        enter();
        try {
            link(id);
            return core.dir.linkName(id);
        } finally {
            exit();
        }
    }

    /** @return the id of the first ({@code second} false) or second mass of an interaction. */
    public int linkEnd(int id, boolean second) {
        enter();
        try {
            link(id);
            return second ? core.engine.linkMassB(id) : core.engine.linkMassA(id);
        } finally {
            exit();
        }
    }

    /** A number of an interaction. */
    public enum LinkParam { STIFFNESS, DAMPING, LENGTH, DISTANCE, ELONGATION, PLANE_POSITION, PLANE_AXIS, ATTRACTION }

    public double linkParam(int id, LinkParam p) {
        enter();
        try {
            link(id);
            switch (p) {
                case STIFFNESS:
                    return core.params.linkStiffness(id);
                case DAMPING:
                    return core.params.linkDamping(id);
                case LENGTH:
                    return core.params.linkLength(id);
                case DISTANCE:
                    return core.params.linkDistance(id);
                case ELONGATION:
                    return core.params.linkElongation(id);
                case PLANE_POSITION:
                    return core.params.planePosition("getPlanePosition", id);
                case PLANE_AXIS:
                    return core.params.planeAxis("getOrientation", id);
                default:
                    return core.params.attraction("getAttraction", id);
            }
        } finally {
            exit();
        }
    }

    /**
     * Sets a parameter of an interaction ({@code op} names the handle's setter in messages): stiffness, damping,
     * length (rest length, threshold, radius, limit), plane position or attraction.
     */
    public void setLinkParam(int id, String op, LinkParam p, double v) {
        enterChange();
        try {
            link(id);
            switch (p) {
                case STIFFNESS:
                    core.params.setLink(op, id, v, Double.NaN, Double.NaN);
                    break;
                case DAMPING:
                    core.params.setLink(op, id, Double.NaN, v, Double.NaN);
                    break;
                case LENGTH:
                    core.params.setLink(op, id, Double.NaN, Double.NaN, v);
                    break;
                case PLANE_POSITION:
                    core.params.setPlanePosition(op, id, v);
                    break;
                case ATTRACTION:
                    core.params.setAttraction(op, id, v);
                    break;
                default:
                    throw new IllegalArgumentException(op + ": " + p + " cannot be set");
            }
        } finally {
            exit();
        }
    }

    /** Reads parameter {@code index} beyond stiffness, damping and length of a nonlinear interaction. */
    public double linkAux(int id, String op, int index) {
        enter();
        try {
            link(id);
            return core.params.aux(op, id, index);
        } finally {
            exit();
        }
    }

    /** Sets parameter {@code index} beyond stiffness, damping and length of a nonlinear interaction. */
    public void setLinkAux(int id, String op, int index, double v) {
        enterChange();
        try {
            link(id);
            core.params.setAux(op, id, index, v);
        } finally {
            exit();
        }
    }
}
