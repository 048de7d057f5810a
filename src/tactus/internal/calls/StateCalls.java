package tactus.internal.calls;

import tactus.Vect3D;
import tactus.internal.model.Check;
import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/**
 * The facade calls on the state of masses: positions, velocities, forces, impulses and velocity control, and the
 * haptic avatar. Each enters the model once and hands the work to its room. Not API.
 */
public final class StateCalls extends Calls {
    public StateCalls(ModelCore core, ModelLock gate) {
        super(core, gate);
    }

    public Vect3D getMatPosition(String name, Vect3D out) {
        enter();
        try {
            return core.state.position(core.dir.massId("getMatPosition", name), out);
        } finally {
            exit();
        }
    }

    public Vect3D getMatPosAt(int i) {
        enter();
        try {
            int id = paperMassAt("getMatPosAt", i, "a zero vector was returned");
            if (id < 0) {
                return new Vect3D();
            }
            return core.state.position(id, new Vect3D());
        } finally {
            exit();
        }
    }

    public Vect3D getMatVelocity(String name) {
        enter();
        try {
            return core.state.velocity(core.dir.massId("getMatVelocity", name), new Vect3D());
        } finally {
            exit();
        }
    }

    public Vect3D getMatVelAt(int i) {
        enter();
        try {
            int id = paperMassAt("getMatVelAt", i, "a zero vector was returned");
            if (id < 0) {
                return new Vect3D();
            }
            return core.state.velocity(id, new Vect3D());
        } finally {
            exit();
        }
    }

    public Vect3D getMatForce(String name) {
        enter();
        try {
            return core.state.force(core.dir.massId("getMatForce", name), new Vect3D());
        } finally {
            exit();
        }
    }

    public Vect3D getMatFrcAt(int i) {
        enter();
        try {
            int id = paperMassAt("getMatFrcAt", i, "a zero vector was returned");
            if (id < 0) {
                return new Vect3D();
            }
            return core.state.force(id, new Vect3D());
        } finally {
            exit();
        }
    }

    public void setMatPosition(String name, Vect3D pos) {
        Check.vector("setMatPosition", name, "pos", pos);
        enterChange();
        try {
            core.state.setPosition(core.dir.massId("setMatPosition", name), pos);
        } finally {
            exit();
        }
    }

    public void setMatPosAt(int i, Vect3D pos) {
        enterChange();
        try {
            int id = core.dir.massAt("setMatPosAt", i);
            Check.vector("setMatPosAt", core.dir.massName(id), "pos", pos);
            core.state.setPosition(id, pos);
        } finally {
            exit();
        }
    }

    public void setMoveKeepsLinkHistory(boolean keep) {
        enter();
        try {
            core.state.moveKeepsLinkHistory = keep;
        } finally {
            exit();
        }
    }

    public boolean getMoveKeepsLinkHistory() {
        return core.state.moveKeepsLinkHistory;
    }

    public void setMatVelocity(String name, Vect3D vel) {
        Check.vector("setMatVelocity", name, "vel", vel);
        enterChange();
        try {
            core.state.setVelocity("setMatVelocity", core.dir.massId("setMatVelocity", name), vel);
        } finally {
            exit();
        }
    }

    public void triggerForceImpulse(String name, double fx, double fy, double fz) {
        checkForce("triggerForceImpulse", name, fx, fy, fz);
        enterChange();
        try {
            core.state.addImpulse(core.dir.massId("triggerForceImpulse", name), fx, fy, fz);
        } finally {
            exit();
        }
    }

    public void triggerForceImpulse(int i, double fx, double fy, double fz) {
        checkForce("triggerForceImpulse", String.valueOf(i), fx, fy, fz);
        enterChange();
        try {
            core.state.addImpulse(core.dir.massAt("triggerForceImpulse", i), fx, fy, fz);
        } finally {
            exit();
        }
    }

    public void triggerVelocityControl(String name, double vx, double vy, double vz) {
        checkForce("triggerVelocityControl", name, vx, vy, vz);
        structuralDo(() -> {
            core.state.driveVelocity("triggerVelocityControl", core.dir.massId("triggerVelocityControl", name), vx,
                    vy, vz);
        });
    }

    public void triggerVelocityControl(int i, double vx, double vy, double vz) {
        checkForce("triggerVelocityControl", String.valueOf(i), vx, vy, vz);
        structuralDo(() -> {
            core.state.driveVelocity("triggerVelocityControl", core.dir.massAt("triggerVelocityControl", i), vx, vy,
                    vz);
        });
    }

    public void stopVelocityControl(String name) {
        structuralDo(() -> {
            core.state.stopDriving(core.dir.massId("stopVelocityControl", name));
        });
    }

    public void stopVelocityControl(int i) {
        structuralDo(() -> {
            core.state.stopDriving(core.dir.massAt("stopVelocityControl", i));
        });
    }

    public void setHapticPosition(String name, Vect3D pos) {
        Check.vector("setHapticPosition", name, "pos", pos);
        enterChange();
        try {
            int id = core.dir.massId("setHapticPosition", name);
            if (core.state.paperIsInput("setHapticPosition", id, "nothing was changed")) {
                core.state.setInputTarget(id, pos.x, pos.y, pos.z);
            }
        } finally {
            exit();
        }
    }

    public Vect3D getHapticForce(String name) {
        return hapticForce(name, new Vect3D(), true);
    }

    public long getHapticForceCounted(String name, Vect3D out) {
        if (out == null) {
            throw Check.fail("getHapticForceCounted", name, "out must not be null");
        }
        enter();
        try {
            int id = core.dir.massId("getHapticForceCounted", name);
            core.state.requireInput("getHapticForceCounted", id);
            return core.state.takeAvatarForceCounted(id, out);
        } finally {
            exit();
        }
    }

    public Vect3D getHapticForce(String name, Vect3D out) {
        return hapticForce(name, out, false);
    }

    private Vect3D hapticForce(String name, Vect3D out, boolean paper) {
        enter();
        try {
            int id = core.dir.massId("getHapticForce", name);
            if (!paper) {
                core.state.requireInput("getHapticForce", id);
            } else if (!core.state.paperIsInput("getHapticForce", id, "a zero force was returned")) {
                return out.set(0, 0, 0);
            }
            return core.state.takeAvatarForce(id, out);
        } finally {
            exit();
        }
    }
}
