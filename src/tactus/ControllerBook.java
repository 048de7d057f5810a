package tactus;

import java.util.LinkedHashMap;
import tactus.internal.model.Ramps;

/**
 * A model's parameter controllers by name, in creation order, and their ramps as the stepping calls see them
 * ({@link Ramps}). Every method assumes the caller is inside a facade call. Not API.
 */
final class ControllerBook implements Ramps {
    private final LinkedHashMap<String, ParamController> controllers = new LinkedHashMap<>();
    /** The same controllers as an array, so that the stepping path checks them without allocating an iterator. */
    private volatile ParamController[] controllerArray = new ParamController[0];

    /** Adds or replaces a named parameter controller. */
    public void put(String name, ParamController pc) {
        controllers.put(name, pc);
        controllerArray = controllers.values().toArray(new ParamController[0]);
    }

    /** {@return the named parameter controller, or null} */
    public ParamController get(String name) {
        return controllers.get(name);
    }

    @Override
    public void clear() {
        controllers.clear();
        controllerArray = new ParamController[0];
    }

    @Override
    public boolean ramping() {
        for (ParamController pc : controllerArray) {
            if (pc.isRamping()) {
                return true;
            }
        }
        return false;
    }

    @Override
    public void advanceAll() {
        for (ParamController pc : controllerArray) {
            pc.updateParams();
        }
    }
}
