package tactus.sketch;

import java.io.File;
import java.lang.reflect.Field;

import processing.core.PApplet;

/**
 * The main class of the child JVM that {@link SketchHarness} starts under Xvfb: it runs one compiled sketch
 * until it has drawn a given number of frames, saves the frame at half that count and the last frame as PNG, prints
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

    private final PApplet sketch;
    private final int frames;
    private final File png;

    private SketchRunner(PApplet sketch, int frames, File png) {
        this.sketch = sketch;
        this.frames = frames;
        this.png = png;
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
        sketch.save(png.getAbsolutePath());
        System.out.println(SketchHarness.DONE_MARKER + sketch.frameCount);
        // halt, not exit: nothing may wait here for the animation thread that is calling us.
        halt(png.isFile() ? 0 : 4);
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
        SketchRunner runner = new SketchRunner(sketch, Integer.parseInt(args[1]), new File(args[2]));
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
}
