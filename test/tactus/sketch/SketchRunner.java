package tactus.sketch;

import java.io.File;
import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.List;

import processing.core.PApplet;
import processing.core.PConstants;
import processing.event.Event;
import processing.event.KeyEvent;
import processing.event.MouseEvent;

/**
 * The main class of the child JVM that {@link SketchHarness} starts under Xvfb: it runs one compiled sketch
 * until it has drawn a given number of frames, saves the frame at half that count and the last frame as PNG, plays
 * the input script of {@value #INPUT_PROPERTY} if there is one (one event per frame), prints
 * {@code tactus-sketch-runner: frames=N} and ends the JVM with status 0.
 *
 * <p>An exception that escapes the sketch (in {@code setup()}, {@code draw()} or an event) is printed on
 * standard error and ends the JVM with status 3, so that a failing sketch does not wait for the timeout with its
 * window still open.
 *
 * <p>Usage: {@code java tactus.sketch.SketchRunner SketchClass frames frame.png [sketchFolder]}
 */
public final class SketchRunner {

    /** Exit status when an exception escaped the sketch. */
    public static final int EXCEPTION_STATUS = 3;

    /**
     * System property: the input script played after the last checked frame, comma-separated items:
     * {@code k<n>} presses and releases the key of character code n, {@code c<n>} the coded key of key code n
     * (UP is 38), {@code mouse} presses the mouse in the middle of the window, drags it and releases it.
     */
    public static final String INPUT_PROPERTY = "tactus.sketch.input";
    /** What the runner prints on standard output with the number of input events it played. */
    static final String INPUT_MARKER = "tactus-sketch-runner: input events=";
    /** Frames drawn after the last input event, so that what it triggered runs. */
    static final int SETTLE_FRAMES = 10;

    private final PApplet sketch;
    private final int frames;
    private final File png;
    private final List<Event> input;

    private SketchRunner(PApplet sketch, int frames, File png, List<Event> input) {
        this.sketch = sketch;
        this.frames = frames;
        this.png = png;
        this.input = input;
    }

    /**
     * Called by Processing after every {@code draw()} (registered as the sketch's {@code post} method); saves the
     * frame and ends the JVM once enough frames have been drawn.
     */
    public void post() {
        if (sketch.frameCount == frames / 2 && frames >= 2) {
            sketch.save(SketchHarness.midFramePath(png.toPath()).toAbsolutePath().toString());
        }
        if (sketch.frameCount < frames) {
            return;
        }
        if (sketch.frameCount == frames) {
            sketch.save(png.getAbsolutePath());
        }
        // Then the scripted input, one event per frame, and a few frames for its effects.
        int step = sketch.frameCount - frames;
        if (step < input.size()) {
            sketch.postEvent(input.get(step));
            return;
        }
        if (step < input.size() + SETTLE_FRAMES && !input.isEmpty()) {
            return;
        }
        System.out.println(INPUT_MARKER + input.size());
        System.out.println(SketchHarness.DONE_MARKER + frames);
        // halt, not exit: nothing may wait here for the animation thread that is calling us.
        halt(png.isFile() ? 0 : 4);
    }

    /**
     * The events of an input script (see {@link #INPUT_PROPERTY}), in order: for each key a press and, one frame
     * later, a release; for {@code mouse}, a press in the middle of the window, two drags and a release.
     *
     * @param script the script, or null for none
     * @param width  the window's width, in pixels
     * @param height the window's height, in pixels
     * @return the events
     * @throws IllegalArgumentException for an item that is not {@code k<char>}, {@code c<keyCode>} or
     *     {@code mouse}
     */
    static List<Event> inputEvents(String script, int width, int height) {
        List<Event> events = new ArrayList<>();
        if (script == null || script.isEmpty()) {
            return events;
        }
        long t = System.currentTimeMillis();
        for (String item : script.split(",", -1)) {
            if (item.equals("mouse")) {
                int x = width / 2;
                int y = height / 2;
                events.add(new MouseEvent(null, t, MouseEvent.PRESS, 0, x, y, PConstants.LEFT, 1));
                events.add(new MouseEvent(null, t, MouseEvent.DRAG, 0, x + width / 8, y, PConstants.LEFT, 1));
                events.add(new MouseEvent(null, t, MouseEvent.DRAG, 0, x + width / 8, y + height / 8,
                        PConstants.LEFT, 1));
                events.add(new MouseEvent(null, t, MouseEvent.RELEASE, 0, x + width / 8, y + height / 8,
                        PConstants.LEFT, 1));
            } else if (item.length() >= 2 && item.charAt(0) == 'k') {
                char c = (char) Integer.parseInt(item.substring(1));
                // The key code a real keyboard gives with that character (VK_QUOTE for a quote, not 39 = RIGHT).
                int code = java.awt.event.KeyEvent.getExtendedKeyCodeForChar(c);
                events.add(new KeyEvent(null, t, KeyEvent.PRESS, 0, c, code));
                events.add(new KeyEvent(null, t, KeyEvent.RELEASE, 0, c, code));
            } else if (item.length() >= 2 && item.charAt(0) == 'c') {
                int code = Integer.parseInt(item.substring(1));
                events.add(new KeyEvent(null, t, KeyEvent.PRESS, 0, (char) PConstants.CODED, code));
                events.add(new KeyEvent(null, t, KeyEvent.RELEASE, 0, (char) PConstants.CODED, code));
            } else {
                throw new IllegalArgumentException("input item '" + item + "' is not k<char code>, c<keyCode> or mouse");
            }
        }
        return events;
    }

    /**
     * Runs a sketch.
     *
     * @param args the sketch class name, the number of frames, the PNG file to save the last frame to
     * @throws Exception if the sketch cannot be created
     */
    public static void main(String[] args) throws Exception {
        if (args.length != 3 && args.length != 4) {
            System.err.println("usage: SketchRunner SketchClass frames frame.png [sketchFolder]");
            System.exit(2);
        }
        PApplet sketch = (PApplet) Class.forName(args[0]).getDeclaredConstructor().newInstance();
        // The window's size is known once setup() has run; the events are made when the script starts.
        SketchRunner runner = new SketchRunner(sketch, Integer.parseInt(args[1]), new File(args[2]),
                new LazyInput(sketch, System.getProperty(INPUT_PROPERTY)));
        sketch.registerMethod("post", runner);
        // As the editor does: --sketch-path makes sketchPath() and dataPath() point into the sketch's folder.
        PApplet.runSketch(args.length == 4
                ? new String[] {"--location=0,0", "--sketch-path=" + args[3], args[0]}
                : new String[] {"--location=0,0", args[0]}, sketch);
        // runSketch installs Processing's own default handler, which prints the exception, keeps it in
        // PApplet.uncaughtThrowable (for the editor) and lets the window live on. Replace it from now on, and
        // watch that field for what was thrown before (in setup(), on the animation thread).
        Thread.setDefaultUncaughtExceptionHandler((thread, e) -> {
            e.printStackTrace();
            stopOnException(thread.getName());
        });
        Field thrown = null;
        try {
            thrown = PApplet.class.getDeclaredField("uncaughtThrowable");
            thrown.setAccessible(true);
        } catch (ReflectiveOperationException | RuntimeException e) {
            System.out.println("tactus-sketch-runner: cannot watch PApplet.uncaughtThrowable (" + e + ")");
        }
        while (thrown != null) {
            Thread.sleep(20);
            if (thrown.get(null) != null) {
                stopOnException("the sketch's animation thread");
            }
        }
    }

    private static void stopOnException(String where) {
        System.err.println("tactus-sketch-runner: an exception escaped the sketch in " + where + "; stopping");
        halt(EXCEPTION_STATUS);
    }

    /** Prints the status (xvfb-run may replace the JVM's own with one of its own errors) and ends the JVM. */
    private static void halt(int status) {
        System.out.println(SketchHarness.STATUS_MARKER + status);
        System.out.flush();
        System.err.flush();
        Runtime.getRuntime().halt(status);
    }

    /** The input events, made from the script the first time they are needed (after setup() set the size). */
    private static final class LazyInput extends java.util.AbstractList<Event> {
        private final PApplet sketch;
        private final String script;
        private List<Event> events;

        LazyInput(PApplet sketch, String script) {
            this.sketch = sketch;
            this.script = script;
        }

        private List<Event> events() {
            if (events == null) {
                events = inputEvents(script, sketch.width, sketch.height);
            }
            return events;
        }

        @Override
        public Event get(int i) {
            return events().get(i);
        }

        @Override
        public int size() {
            return events().size();
        }
    }
}
