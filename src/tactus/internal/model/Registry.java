package tactus.internal.model;

import java.util.Arrays;
import java.util.HashMap;

/**
 * Names and insertion order of the live modules of one family (masses or interactions): name to id, id to
 * name, and the index of each live module in insertion order.
 *
 * <p>A registry either keeps names unique (masses) or lets several modules share one name (interactions, as
 * the paper's sketches do: seventy contacts all called "col"). With shared names, {@link #id(String)} is the
 * first live module of that name in insertion order, which is how the paper's engine resolves them.
 *
 * <p>Removals are lazy: a removed id is marked, and the insertion order is compacted once, when it is next read,
 * so that removing k modules of N costs O(k + N), not O(k N).
 */
public final class Registry {
    private final boolean uniqueNames;
    /** Name to the ids that carry it, in insertion order (almost always one). */
    private final HashMap<String, int[]> byName = new HashMap<>();
    private String[] names = new String[16];
    private int[] order = new int[16];
    private int size;
    private int[] indexOfId = new int[0];
    private boolean indexStale = true;
    private boolean[] removed = new boolean[16];   // ids removed but still in order[] until the next compaction
    private int pending;                           // how many of those
    private long compactions;

    public Registry(boolean uniqueNames) {
        this.uniqueNames = uniqueNames;
    }

    /** @return true when names must be unique in this registry. */
    public boolean uniqueNames() {
        return uniqueNames;
    }

    public void add(String name, int id) {
        if (uniqueNames && byName.containsKey(name)) {
            throw new IllegalStateException("duplicate name \"" + name + "\" in a unique registry");
        }
        if (id >= names.length) {
            names = Arrays.copyOf(names, Math.max(id + 1, names.length * 2));
        }
        if (id >= removed.length) {
            removed = Arrays.copyOf(removed, Math.max(id + 1, removed.length * 2));
        }
        if (removed[id]) {
            compact();   // the id comes back before its removal was compacted away
        }
        if (size == order.length) {
            order = Arrays.copyOf(order, order.length * 2);
        }
        names[id] = name;
        int[] ids = byName.get(name);
        if (ids == null) {
            byName.put(name, new int[] {id});
        } else {
            int[] grown = Arrays.copyOf(ids, ids.length + 1);
            grown[ids.length] = id;
            byName.put(name, grown);
        }
        order[size++] = id;
        indexStale = true;
    }

    public void remove(int id) {
        String name = names[id];
        int[] ids = byName.get(name);
        if (ids != null) {
            int[] kept = new int[ids.length];
            int n = 0;
            for (int other : ids) {
                if (other != id) {
                    kept[n++] = other;
                }
            }
            if (n == 0) {
                byName.remove(name);
            } else {
                byName.put(name, Arrays.copyOf(kept, n));
            }
        }
        if (!removed[id]) {
            removed[id] = true;
            pending++;
        }
        indexStale = true;
    }

    /** Drops the removed ids from the insertion order, in one pass. */
    private void compact() {
        if (pending == 0) {
            return;
        }
        int w = 0;
        for (int r = 0; r < size; r++) {
            int id = order[r];
            if (removed[id]) {
                removed[id] = false;
            } else {
                order[w++] = id;
            }
        }
        size = w;
        pending = 0;
        compactions++;
    }

    /** How many times the insertion order was compacted after removals (for the cost tests). */
    public long compactions() {
        return compactions;
    }

    public void clear() {
        byName.clear();
        Arrays.fill(removed, false);
        pending = 0;
        size = 0;
        indexStale = true;
    }

    /** @return the id of the first live module with this name in insertion order, or -1 when there is none. */
    public int id(String name) {
        int[] ids = name == null ? null : byName.get(name);
        return ids == null ? -1 : ids[0];
    }

    /** @return how many live modules carry this name (0, 1, or more for shared interaction names). */
    public int count(String name) {
        int[] ids = name == null ? null : byName.get(name);
        return ids == null ? 0 : ids.length;
    }

    public String name(int id) {
        return names[id];
    }

    public int size() {
        return size - pending;
    }

    /** @return the id at an insertion-order index, or -1 when the index is out of range. */
    public int idAt(int index) {
        compact();
        return index >= 0 && index < size ? order[index] : -1;
    }

    /** @return the insertion-order index of a live id, or -1. */
    public int indexOf(int id) {
        if (indexStale) {
            compact();
            indexOfId = new int[names.length];
            Arrays.fill(indexOfId, -1);
            for (int i = 0; i < size; i++) {
                indexOfId[order[i]] = i;
            }
            indexStale = false;
        }
        return id >= 0 && id < indexOfId.length ? indexOfId[id] : -1;
    }

    /** @return a copy of the live ids in insertion order. */
    public int[] ids() {
        compact();
        return Arrays.copyOf(order, size);
    }
}
