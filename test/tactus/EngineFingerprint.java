package tactus;

import java.lang.reflect.Array;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Collection;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

/**
 * Test helper (not a test class): every value reachable from a model's engine, as a list of {@code path=value}
 * lines, so that two fingerprints taken before and after a call show whether the call wrote anything. It walks
 * the engine's object graph by reflection (every field of every {@code tactus.engine} object, arrays, lists), so a
 * new field is covered without touching this class. Doubles are written as their raw bits (bitwise comparison);
 * objects outside the engine (threads, the parallel stepper's JDK parts, lambdas) are written as their class only.
 */
final class EngineFingerprint {
    private final List<String> lines = new ArrayList<>();
    private final Map<Object, Integer> seen = new IdentityHashMap<>();

    private EngineFingerprint() {
    }

    /** @return the fingerprint of a model's engine. */
    static List<String> of(PhysicalModel m) {
        EngineFingerprint f = new EngineFingerprint();
        f.walk("engine", m.core.engine);
        return f.lines;
    }

    /** @return null when both fingerprints are equal, else the first line that differs (before / after). */
    static String firstDifference(List<String> before, List<String> after) {
        int n = Math.min(before.size(), after.size());
        for (int i = 0; i < n; i++) {
            if (!before.get(i).equals(after.get(i))) {
                return before.get(i) + "  ->  " + after.get(i);
            }
        }
        if (before.size() != after.size()) {
            return "length " + before.size() + " -> " + after.size() + " (first extra line: "
                    + (before.size() > n ? before.get(n) : after.get(n)) + ")";
        }
        return null;
    }

    private void walk(String path, Object o) {
        if (o == null) {
            lines.add(path + "=null");
            return;
        }
        Class<?> c = o.getClass();
        if (o instanceof Double) {
            lines.add(path + "=d" + Long.toHexString(Double.doubleToRawLongBits((Double) o)));
            return;
        }
        if (o instanceof Float) {
            lines.add(path + "=f" + Integer.toHexString(Float.floatToRawIntBits((Float) o)));
            return;
        }
        if (o instanceof Number || o instanceof Boolean || o instanceof Character || o instanceof String
                || o instanceof Enum) {
            lines.add(path + "=" + o);
            return;
        }
        Integer ref = seen.get(o);
        if (ref != null) {
            lines.add(path + "=ref#" + ref);
            return;
        }
        if (c.isArray()) {
            seen.put(o, seen.size());
            int n = Array.getLength(o);
            lines.add(path + "=array[" + n + "]");
            for (int i = 0; i < n; i++) {
                walk(path + "[" + i + "]", Array.get(o, i));
            }
            return;
        }
        if (o instanceof Collection) {
            seen.put(o, seen.size());
            int i = 0;
            lines.add(path + "=collection(" + ((Collection<?>) o).size() + ")");
            for (Object e : (Collection<?>) o) {
                walk(path + "<" + i++ + ">", e);
            }
            return;
        }
        boolean engineObject = c.getName().startsWith("tactus.engine.") && !c.isSynthetic()
                && !c.getName().contains("$$Lambda");
        if (!engineObject) {
            lines.add(path + "=" + (c.isSynthetic() || c.getName().contains("$$Lambda") ? "lambda" : c.getName()));
            return;
        }
        seen.put(o, seen.size());
        lines.add(path + "=" + c.getSimpleName());
        for (Class<?> k = c; k != null && k != Object.class; k = k.getSuperclass()) {
            for (Field f : k.getDeclaredFields()) {
                if (Modifier.isStatic(f.getModifiers())) {
                    continue;
                }
                f.setAccessible(true);
                try {
                    walk(path + "." + f.getName(), f.get(o));
                } catch (IllegalAccessException e) {
                    throw new AssertionError(e);
                }
            }
        }
    }
}
