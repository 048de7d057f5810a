package tactus;

import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;

/**
 * Named groups of module ids for grouped parameter changes. Groups hold stable ids, not
 * indices, and drop a module when it is removed, so they never go stale.
 */
final class Subsets {
    private final Map<String, LinkedHashSet<Integer>> groups = new LinkedHashMap<>();

    boolean exists(String name) {
        return groups.containsKey(name);
    }

    /** @return true when the group was created, false when it already existed. */
    boolean create(String name) {
        if (groups.containsKey(name)) {
            return false;
        }
        groups.put(name, new LinkedHashSet<>());
        return true;
    }

    void add(String group, int id) {
        groups.get(group).add(id);
    }

    void remove(String group, int id) {
        groups.get(group).remove(id);
    }

    /** Removes an id from every group (the module was deleted). */
    void forget(int id) {
        for (Set<Integer> s : groups.values()) {
            s.remove(id);
        }
    }

    Set<Integer> members(String group) {
        return groups.get(group);
    }

    void clear() {
        groups.clear();
    }
}
