package tactus.internal.model;

import java.util.Arrays;
import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.Interaction;
import tactus.Mass;
import tactus.PhysicalModel;

/**
 * The model's directory: names, insertion-order indices and handles of the live masses and interactions, and
 * the look-ups that turn a user's name or index into an engine id with an error that names what was asked.
 * Mass names are unique; interaction names may repeat (the first live match wins). The caller holds the
 * model's lock.
 */
public final class Directory {
    public final Registry mats = new Registry(true);
    public final Registry links = new Registry(false);
    private final Engine engine;
    private Mass[] massHandles = new Mass[16];
    private Interaction[] linkHandles = new Interaction[16];

    public Directory(Engine engine) {
        this.engine = engine;
    }

    // ---------------------------------------------------------------- look-ups with user-facing errors

    /** @return the id of the mass with this name; throws naming the operation and the name. */
    public int massId(String op, String name) {
        int id = mats.id(name);
        if (id < 0) {
            throw new IllegalArgumentException(op + "(\"" + name + "\"): no mass with this name");
        }
        return id;
    }

    /** @return the id of the first interaction with this name; throws naming the operation and the name. */
    public int linkId(String op, String name) {
        int id = links.id(name);
        if (id < 0) {
            throw new IllegalArgumentException(op + "(\"" + name + "\"): no interaction with this name");
        }
        return id;
    }

    /** @return the id of the mass at an insertion-order index; throws naming the range. */
    public int massAt(String op, int i) {
        int id = mats.idAt(i);
        if (id < 0) {
            throw new IllegalArgumentException(op + "(" + i + "): mass index out of range"
                    + range(mats.size()));
        }
        return id;
    }

    /** @return the id of the interaction at an insertion-order index; throws naming the range. */
    public int linkAt(String op, int i) {
        int id = links.idAt(i);
        if (id < 0) {
            throw new IllegalArgumentException(op + "(" + i + "): interaction index out of range"
                    + range(links.size()));
        }
        return id;
    }

    private static String range(int size) {
        return size == 0 ? " (the model has none)" : " 0.." + (size - 1);
    }

    /** @return the id of a mass named as the end of an interaction being built. */
    public int endMass(String op, String element, String massName) {
        int id = mats.id(massName);
        if (id < 0) {
            throw Check.fail(op, element, "unknown mass \"" + massName + "\"");
        }
        return id;
    }

    public String massName(int id) {
        return mats.name(id);
    }

    public String linkName(int id) {
        return links.name(id);
    }

    public MassKind massKind(int id) {
        return engine.massKind(id);
    }

    public LinkKind linkKind(int id) {
        return engine.linkKind(id);
    }

    /** @return "Mass3D \"name\"", for messages. */
    public String describeMass(int id) {
        return engine.massKind(id).label() + " \"" + mats.name(id) + "\"";
    }

    // ---------------------------------------------------------------- registration and handles

    public Mass registerMass(PhysicalModel model, String name, int id, MassKind kind) {
        mats.add(name, id);
        return storeMassHandle(model, id, kind);
    }

    /** Replaces the handle of a live mass (its kind changed, for example to a fixed point). */
    public Mass storeMassHandle(PhysicalModel model, int id, MassKind kind) {
        if (id >= massHandles.length) {
            massHandles = Arrays.copyOf(massHandles, Math.max(id + 1, massHandles.length * 2));
        }
        if (massHandles[id] != null) {
            ApiAccess.get().retire(massHandles[id]);
        }
        Mass h = ApiAccess.get().newMassHandle(model, id, kind);
        massHandles[id] = h;
        return h;
    }

    public Interaction registerLink(PhysicalModel model, String name, int id, LinkKind kind) {
        links.add(name, id);
        if (id >= linkHandles.length) {
            linkHandles = Arrays.copyOf(linkHandles, Math.max(id + 1, linkHandles.length * 2));
        }
        Interaction h = ApiAccess.get().newLinkHandle(model, id, kind);
        linkHandles[id] = h;
        return h;
    }

    public Mass massHandle(int id) {
        return massHandles[id];
    }

    public Interaction linkHandle(int id) {
        return linkHandles[id];
    }

    public void forgetMass(int id) {
        mats.remove(id);
        ApiAccess.get().retire(massHandles[id]);
        massHandles[id] = null;
    }

    public void forgetLink(int id) {
        links.remove(id);
        ApiAccess.get().retire(linkHandles[id]);
        linkHandles[id] = null;
    }

    public void clear() {
        for (int id : mats.ids()) {
            ApiAccess.get().retire(massHandles[id]);
        }
        for (int id : links.ids()) {
            ApiAccess.get().retire(linkHandles[id]);
        }
        Arrays.fill(massHandles, null);
        Arrays.fill(linkHandles, null);
        mats.clear();
        links.clear();
    }
}
