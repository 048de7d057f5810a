package tactus.internal.model;

import java.util.Arrays;
import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.engine.MassKind;

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
    private final HandleFactory handles;
    private Object[] massHandles = new Object[16];
    private Object[] linkHandles = new Object[16];

    public Directory(Engine engine, HandleFactory handles) {
        this.engine = engine;
        this.handles = handles;
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

    public Object registerMass(String name, int id, MassKind kind) {
        mats.add(name, id);
        return storeMassHandle(id, kind);
    }

    /** Replaces the handle of a live mass (its kind changed, for example to a fixed point). */
    public Object storeMassHandle(int id, MassKind kind) {
        if (id >= massHandles.length) {
            massHandles = Arrays.copyOf(massHandles, Math.max(id + 1, massHandles.length * 2));
        }
        if (massHandles[id] != null) {
            handles.retire(massHandles[id]);
        }
        Object h = handles.newMass(id, kind);
        massHandles[id] = h;
        return h;
    }

    public Object registerLink(String name, int id, LinkKind kind) {
        links.add(name, id);
        if (id >= linkHandles.length) {
            linkHandles = Arrays.copyOf(linkHandles, Math.max(id + 1, linkHandles.length * 2));
        }
        Object h = handles.newLink(id, kind);
        linkHandles[id] = h;
        return h;
    }

    public Object massHandle(int id) {
        return massHandles[id];
    }

    public Object linkHandle(int id) {
        return linkHandles[id];
    }

    public void forgetMass(int id) {
        mats.remove(id);
        handles.retire(massHandles[id]);
        massHandles[id] = null;
    }

    public void forgetLink(int id) {
        links.remove(id);
        handles.retire(linkHandles[id]);
        linkHandles[id] = null;
    }

    public void clear() {
        for (int id : mats.ids()) {
            handles.retire(massHandles[id]);
        }
        for (int id : links.ids()) {
            handles.retire(linkHandles[id]);
        }
        Arrays.fill(massHandles, null);
        Arrays.fill(linkHandles, null);
        mats.clear();
        links.clear();
    }
}
