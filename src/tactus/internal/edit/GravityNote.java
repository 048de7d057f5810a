package tactus.internal.edit;

import tactus.engine.MassKind;
import tactus.Vect3D;
import tactus.internal.model.Registry;
import tactus.internal.model.ModelBase;

/**
 * The one-time note of a model whose 1D masses (Mass1D, Osc1D) feel gravity: Tactus gives them the z component of
 * gravity like every other mass, the paper's engine left them out of it. Checked when gravity or its direction
 * changes and when a 1D mass is added, never while stepping; printed at most once per model. The caller holds the
 * model's lock.
 */
public final class GravityNote {
    private final ModelBase c;
    /** Scratch for the gravity direction: the check allocates nothing (a sketch may set gravity from its audio thread). */
    private final Vect3D dir = new Vect3D();
    private boolean told;

    public GravityNote(ModelBase core) {
        this.c = core;
    }

    /** @return true once the note was printed for this model. */
    public boolean told() {
        return told;
    }

    /** After gravity or its direction changed: prints the note if the model has a 1D mass. */
    public void afterGravityChange() {
        if (told || !pullsAlongZ()) {
            return;
        }
        Registry mats = c.dir.mats;
        for (int i = 0, n = mats.size(); i < n; i++) {
            int id = mats.idAt(i);
            if (isOneD(c.dir.massKind(id))) {
                tell(c.dir.massName(id));
                return;
            }
        }
    }

    /** After a mass was added: prints the note if it is a 1D mass and gravity pulls along z. */
    public void afterMassAdded(MassKind kind, String name) {
        if (!told && isOneD(kind) && pullsAlongZ()) {
            tell(name);
        }
    }

    private boolean pullsAlongZ() {
        return c.time.gravity() != 0 && c.time.gravityDirection(dir).z != 0;
    }

    private static boolean isOneD(MassKind kind) {
        return kind == MassKind.MASS1D || kind == MassKind.OSC1D;
    }

    private void tell(String massName) {
        told = true;
        System.err.println(message(massName, c.time.gravity(), c.time.gravityDirection(dir)));
    }

    /** @return the note's text, naming one 1D mass, the gravity and its direction. */
    public static String message(String massName, double gravity, Vect3D direction) {
        return "Note: 1D masses feel gravity in Tactus (\"" + massName + "\" and every Mass1D and Osc1D of this model: "
                + "setGravity(" + gravity + "), direction " + direction + ", so they are pulled along z by "
                + gravity * direction.z + "). The paper's engine (miPhysics) left 1D masses out of gravity; to sound "
                + "as it did, keep gravity at 0 in this model, or give the gravity a direction with no z "
                + "component (setGravityDirection). This note is printed once per model.";
    }
}
