package tactus.internal.model;

import java.util.Arrays;
import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.engine.MassKind;

/**
 * The model's directory: names, insertion-order indices and stamps of the live masses and interactions, and
 * the look-ups that turn a user's name or index into an engine id with an error that names what was asked.
 * Mass names are unique; interaction names may repeat (the first live match wins). The caller holds the
 * model's lock.
 */
public final class Directory {
    public final Registry mats = new Registry(true);
    public final Registry links = new Registry(false);
    private final Engine engine;
    private final ModuleListener listener;
    /** Per mass id: its stamp (0 before it joined), see {@link #massStamp}. */
    private int[] massStamps = new int[16];
    /** Per mass id: true once it left the model (ids are never reused). */
    private boolean[] massGone = new boolean[16];
    /** Per interaction id: true while it is part of the model. */
    private boolean[] linkLive = new boolean[16];

    public Directory(Engine engine, ModuleListener listener) {
        this.engine = engine;
        this.listener = listener;
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

    // ---------------------------------------------------------------- registration and liveness

    /** @return the stamp of a live mass: it changes when the mass takes a new kind (made fixed). */
    public int massStamp(int id) {
        return id < massStamps.length ? massStamps[id] : 0;
    }

    /** Throws the handle's {@code IllegalStateException} unless mass {@code id} is live under {@code stamp}. */
    public void checkMass(int id, int stamp) {
        if (massStamp(id) != stamp || massGone[id]) {
            throw gone("mass");
        }
    }

    /** Throws the handle's {@code IllegalStateException} unless interaction {@code id} is live. */
    public void checkLink(int id) {
        if (id >= linkLive.length || !linkLive[id]) {
            throw gone("interaction");
        }
    }

    private static IllegalStateException gone(String what) {
        return new IllegalStateException("this " + what + " handle is no longer part of its model (removed, cleared"
                + " or made fixed)");
    }

    public void registerMass(String name, int id, MassKind kind) {
        mats.add(name, id);
        retypeMass(id, kind);
    }

    /** Gives a live mass a new stamp and tells the listener (it was added, or its kind changed to a fixed point). */
    public void retypeMass(int id, MassKind kind) {
        if (id >= massStamps.length) {
            massStamps = Arrays.copyOf(massStamps, Math.max(id + 1, massStamps.length * 2));
            massGone = Arrays.copyOf(massGone, massStamps.length);
        }
        if (massStamps[id] != 0) {
            listener.massGone(id);
        }
        massStamps[id]++;
        listener.massAdded(id, kind, massStamps[id]);
    }

    public void registerLink(String name, int id, LinkKind kind) {
        links.add(name, id);
        if (id >= linkLive.length) {
            linkLive = Arrays.copyOf(linkLive, Math.max(id + 1, linkLive.length * 2));
        }
        linkLive[id] = true;
        listener.linkAdded(id, kind);
    }

    public void forgetMass(int id) {
        mats.remove(id);
        massGone[id] = true;
        listener.massGone(id);
    }

    public void forgetLink(int id) {
        links.remove(id);
        linkLive[id] = false;
        listener.linkGone(id);
    }

    public void clear() {
        for (int id : mats.ids()) {
            massGone[id] = true;
            listener.massGone(id);
        }
        for (int id : links.ids()) {
            linkLive[id] = false;
            listener.linkGone(id);
        }
        mats.clear();
        links.clear();
    }
}
