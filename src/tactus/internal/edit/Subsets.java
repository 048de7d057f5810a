package tactus.internal.edit;

import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;

/**
 * Named groups of module ids for grouped parameter changes. Groups hold stable ids, not
 * indices, and drop a module when it is removed, so they never go stale.
 */
public final class Subsets {
    private final Map<String, LinkedHashSet<Integer>> groups = new LinkedHashMap<>();

    public boolean exists(String name) {
        return groups.containsKey(name);
    }

    /** @return true when the group was created, false when it already existed. */
    public boolean create(String name) {
        if (groups.containsKey(name)) {
            return false;
        }
        groups.put(name, new LinkedHashSet<>());
        return true;
    }

    public void add(String group, int id) {
        groups.get(group).add(id);
    }

    public void remove(String group, int id) {
        groups.get(group).remove(id);
    }

    /** Removes an id from every group (the module was deleted). */
    public void forget(int id) {
        for (Set<Integer> s : groups.values()) {
            s.remove(id);
        }
    }

    public Set<Integer> members(String group) {
        return groups.get(group);
    }

    public void clear() {
        groups.clear();
    }
}
