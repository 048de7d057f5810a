package tactus;

import java.io.File;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;

/**
 * Finds and calls a sketch's own {@code void name(File)} method by reflection, the way Processing's
 * {@code selectInput(prompt, "name")} calls its callback: the method must be public (the Processing editor makes
 * a sketch's methods public), and an exception it throws is printed, never passed on.
 */
final class SketchCallback {
    private SketchCallback() {
    }

    /** @return the sketch's public {@code name(File)} method, or null when it has none (or no sketch is given). */
    static Method find(Object sketch, String name) {
        if (sketch == null) {
            return null;
        }
        try {
            Method m = sketch.getClass().getMethod(name, File.class);
            return Modifier.isStatic(m.getModifiers()) ? null : m;
        } catch (NoSuchMethodException e) {
            return null;
        }
    }

    /** Calls {@code handler} on the sketch with the file; prints what it throws, prefixed with {@code who}. */
    static void call(Method handler, Object sketch, File file, String who) {
        try {
            handler.invoke(sketch, file);
        } catch (InvocationTargetException e) {
            System.err.println(who + ": the sketch's " + handler.getName() + "(File) threw " + e.getCause());
            e.getCause().printStackTrace();
        } catch (IllegalAccessException e) {
            System.err.println(who + ": cannot call the sketch's " + handler.getName() + "(File): " + e.getMessage());
        }
    }

    /**
     * @return the message for a sketch without a usable {@code name(File)} method, naming the call, what the
     *     paper's engine expected and what happens instead
     */
    static String missing(Object sketch, String name, String call, String instead) {
        boolean hidden = false;
        for (Class<?> c = sketch == null ? null : sketch.getClass(); c != null && !hidden; c = c.getSuperclass()) {
            try {
                c.getDeclaredMethod(name, File.class);
                hidden = true;
            } catch (NoSuchMethodException e) {
                // look further up
            }
        }
        String what = sketch == null ? "no sketch was given to the ModelLoader"
                : hidden ? "the sketch's " + name + "(File) method is not public"
                : "the sketch has no " + name + "(File) method";
        return call + ": " + what + "; the paper's engine called the sketch's public void " + name
                + "(File selection) with the chosen file. " + instead + ".";
    }
}
