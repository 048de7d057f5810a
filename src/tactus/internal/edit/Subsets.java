package tactus.internal.edit;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;

/**
 * Named groups of module ids for grouped parameter changes. Groups hold stable ids, not
 * indices, and drop a module when it is removed, so they never go stale. Each id knows its groups, so that
 * forgetting a module costs its own memberships, not a visit of every group.
 */
public final class Subsets {
    private final Map<String, LinkedHashSet<Integer>> groups = new LinkedHashMap<>();
    private final Map<Integer, Set<String>> memberOf = new HashMap<>();

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
        if (groups.get(group).add(id)) {
            memberOf.computeIfAbsent(id, k -> new LinkedHashSet<>(2)).add(group);
        }
    }

    public void remove(String group, int id) {
        if (groups.get(group).remove(id)) {
            Set<String> of = memberOf.get(id);
            of.remove(group);
            if (of.isEmpty()) {
                memberOf.remove(id);
            }
        }
    }

    /** Removes an id from every group it is in (the module was deleted). */
    public void forget(int id) {
        Set<String> of = memberOf.remove(id);
        if (of != null) {
            for (String g : of) {
                groups.get(g).remove(id);
            }
        }
    }

    public Set<Integer> members(String group) {
        return groups.get(group);
    }

    public void clear() {
        groups.clear();
        memberOf.clear();
    }
}
