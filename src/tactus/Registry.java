package tactus;

import java.util.Arrays;
import java.util.HashMap;

/**
 * Names and insertion order of the live modules of one family (masses or interactions):
 * name to id, id to name, and the index of each live module in insertion order.
 */
final class Registry {
    private final HashMap<String, Integer> byName = new HashMap<>();
    private String[] names = new String[16];
    private int[] order = new int[16];
    private int size;
    private int[] indexOfId = new int[0];
    private boolean indexStale = true;

    void add(String name, int id) {
        if (id >= names.length) {
            names = Arrays.copyOf(names, Math.max(id + 1, names.length * 2));
        }
        if (size == order.length) {
            order = Arrays.copyOf(order, order.length * 2);
        }
        names[id] = name;
        byName.put(name, id);
        order[size++] = id;
        indexStale = true;
    }

    void remove(int id) {
        byName.remove(names[id]);
        int w = 0;
        for (int r = 0; r < size; r++) {
            if (order[r] != id) {
                order[w++] = order[r];
            }
        }
        size = w;
        indexStale = true;
    }

    void clear() {
        byName.clear();
        size = 0;
        indexStale = true;
    }

    /** @return the id of a live module, or -1 when no module has that name. */
    int id(String name) {
        Integer id = name == null ? null : byName.get(name);
        return id == null ? -1 : id;
    }

    String name(int id) {
        return names[id];
    }

    int size() {
        return size;
    }

    /** @return the id at an insertion-order index, or -1 when the index is out of range. */
    int idAt(int index) {
        return index >= 0 && index < size ? order[index] : -1;
    }

    /** @return the insertion-order index of a live id. */
    int indexOf(int id) {
        if (indexStale) {
            indexOfId = new int[names.length];
            Arrays.fill(indexOfId, -1);
            for (int i = 0; i < size; i++) {
                indexOfId[order[i]] = i;
            }
            indexStale = false;
        }
        return id < indexOfId.length ? indexOfId[id] : -1;
    }

    int[] ids() {
        return Arrays.copyOf(order, size);
    }
}
