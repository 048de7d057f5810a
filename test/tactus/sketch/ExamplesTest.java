package tactus.sketch;

import static org.junit.jupiter.api.Assertions.assertFalse;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * Runs every example sketch under {@code examples/} (found at any depth, {@code examples/<Group>/<Sketch>/
 * <Sketch>.pde}) as the Processing editor would: the editor's preprocessor, {@code javac} against the built
 * library, then {@value #FRAMES} frames under Xvfb, with a copy of the sketch's folder (and its {@code data/}) as
 * the sketch folder. Each sketch is one test. It passes when:
 * <ul>
 * <li>the sketch exits cleanly with nothing like an exception on standard error and has drawn all its frames;</li>
 * <li>its last frame ({@code build/sketches/<Sketch>/frame.png}) is not blank: at least {@value #MIN_DRAWN_SHARE}
 * of its pixels differ from the background (the most common colour);</li>
 * <li>it does something visible on its own, without keys or mouse: at least {@value #MIN_CHANGED_SHARE} of the
 * pixels changed between the frame at half time ({@code frame-mid.png}) and the last one (except the sketches
 * in {@link #STILL_UNTIL_FIXED});</li>
 * <li>if it plays sound ({@link FrameAndSoundChecks#makesSound}): the WAV file that the headless audio output
 * records when the system property {@value #RECORD_PROPERTY} names it ({@code build/sketches/<Sketch>/audio.wav})
 * is not silent: its RMS, DC removed, is at least {@value #MIN_AC_RMS} of full scale.</li>
 * <li>after the checked frames, every key the sketch reacts to and a mouse drag ({@link #inputScript}) run
 * without an exception, so that the code behind every control runs headless too.</li>
 * </ul>
 */
class ExamplesTest {
    /** Frames each example draws: three seconds at 60 frames per second. */
    static final int FRAMES = 180;
    /**
     * The longest one example may run, JVM start, Xvfb and the input script included, in seconds. A P3D example
     * (software OpenGL under Xvfb) took 27 s on a 2-core machine with a load average of 6; this leaves room.
     */
    static final double TIMEOUT_SECONDS = 120;

    /**
     * The least share of a frame that must differ from its background. One line of 14-pixel text across an
     * 800-pixel window covers about 0.3 % of an 800 x 450 frame; a drawn model covers more. A uniform frame has 0.
     */
    static final double MIN_DRAWN_SHARE = 0.01;
    /**
     * The least share of pixels that must change between the frame at half time and the last frame (1.5 s apart):
     * a moving model changes far more; a changing number in a line of text (a few hundred pixels, under 0.1 % of
     * the smallest example window) does not reach it.
     */
    static final double MIN_CHANGED_SHARE = 0.002;
    /** Channel differences up to this (of 255) count as unchanged, so that dithering does not count as motion. */
    static final int CHANGE_TOLERANCE = 8;

    /** The system property that makes the headless audio output record what it plays to a WAV file. */
    static final String RECORD_PROPERTY = "tactus.audio.record";
    /**
     * The least AC RMS, as a fraction of full scale, of a sketch that plays sound: -60 dBFS. Silence written as
     * 16-bit PCM is exactly 0, and its quantisation noise is near -101 dBFS (one step, 2^-15, over the square root
     * of 12), so -60 dBFS cannot be reached by rounding or by a stuck constant (the mean is removed). Every audio
     * example plays a struck or plucked model, which rings tens of decibels louder than that (the PhyUGen output is
     * scaled to a usable level, around -20 dBFS), so the threshold leaves a margin of about 40 dB both ways.
     */
    static final double MIN_AC_RMS = 1e-3;
    /**
     * Whether a sketch that plays sound must leave a recording. False until the headless audio output implements
     * {@value #RECORD_PROPERTY}; then switch it on. Until then a recording that exists is checked, and a missing
     * one is not an error.
     */
    static final boolean RECORDING_REQUIRED = true;

    /**
     * Examples exempt from the "does something on its own" check, by sketch name, each waiting for its owner to
     * make it move without a mouse. Remove a name as soon as its sketch animates on its own.
     */
    static final Set<String> STILL_UNTIL_FIXED = Set.of();

    static Path examplesRoot() {
        return Paths.get(System.getProperty("tactus.sketch.examples", "examples"));
    }

    @TestFactory
    Stream<DynamicTest> everyExampleRunsLikeInTheEditor() {
        List<Path> sketches = SketchHarness.findSketches(examplesRoot());
        assertFalse(sketches.isEmpty(), "no sketch found under " + examplesRoot().toAbsolutePath());
        return sketches.stream().map(dir -> DynamicTest.dynamicTest(
                examplesRoot().relativize(dir).toString(), dir.toUri(), () -> runExample(dir)));
    }

    static void runExample(Path dir) throws IOException {
        String classpath = SketchHarness.sketchClasspath();
        SketchHarness.requireXvfb();
        SketchHarness.JavaSketch sketch = SketchHarness.preprocess(dir);
        Path work = SketchHarness.workDir(sketch.className);
        Path classes = SketchHarness.compile(sketch, work, classpath);
        // A fresh copy of the sketch's folder: the sketch may write into it (saveModel, saveFrame), and data/ is
        // where loadXML(), dataPath() and ModelLoader find its files.
        Path sketchCopy = work.resolve("sketch");
        deleteTree(sketchCopy);
        copyTree(dir, sketchCopy);
        Path wav = work.resolve("audio.wav");
        Files.deleteIfExists(wav);
        Path png = work.resolve("frame.png");
        String source = pdeSource(dir);
        String input = inputScript(source);
        Map<String, String> props = Map.of(RECORD_PROPERTY, wav.toAbsolutePath().toString(),
                SketchRunner.INPUT_PROPERTY, input);
        SketchHarness.Run run = SketchHarness.run(sketch.className, classes, classpath, FRAMES, png,
                TIMEOUT_SECONDS, sketchCopy, props);
        if (joglStartStarved(run)) {
            // Processing's OpenGL surface gives setup() and the first frame 5 s (processing4 issue 340); software
            // OpenGL under Xvfb on a 2-core machine at load 5-8 took longer twice. Once more, and said.
            System.out.println(sketch.className + ": the OpenGL surface did not start within Processing's 5 s "
                    + "(machine load " + loadAverage() + "); running it once more");
            deleteTree(sketchCopy);
            copyTree(dir, sketchCopy);
            Files.deleteIfExists(wav);
            run = SketchHarness.run(sketch.className, classes, classpath, FRAMES, png, TIMEOUT_SECONDS, sketchCopy,
                    props);
        }
        SketchHarness.check(run, FRAMES);
        int expectedEvents = SketchRunner.inputEvents(input, 100, 100).size();
        if (!run.stdout.contains(SketchRunner.INPUT_MARKER + expectedEvents)) {
            throw new AssertionError(sketch.className + " did not play its " + expectedEvents + " input events ("
                    + input + ")\n" + run.logs());
        }

        double drawn = FrameAndSoundChecks.drawnShare(run.image);
        if (drawn < MIN_DRAWN_SHARE) {
            throw new AssertionError(String.format(Locale.ROOT, "%s: only %.2f %% of the last frame differs from "
                    + "the background (at least %.1f %% expected): a blank frame%n%s", sketch.className,
                    100 * drawn, 100 * MIN_DRAWN_SHARE, run.logs()));
        }
        Path midPng = SketchHarness.midFramePath(png);
        if (!Files.isRegularFile(midPng)) {
            throw new AssertionError(sketch.className + " saved no frame at half time (" + midPng + ")\n"
                    + run.logs());
        }
        BufferedImage mid = ImageIO.read(midPng.toFile());
        double changed = FrameAndSoundChecks.changedShare(mid, run.image, CHANGE_TOLERANCE);
        if (changed < MIN_CHANGED_SHARE && !STILL_UNTIL_FIXED.contains(sketch.className)) {
            throw new AssertionError(String.format(Locale.ROOT, "%s: only %.3f %% of the pixels changed between "
                    + "frame %d and frame %d (at least %.1f %% expected): the sketch does nothing visible on its "
                    + "own%n%s", sketch.className, 100 * changed, FRAMES / 2, FRAMES, 100 * MIN_CHANGED_SHARE,
                    run.logs()));
        }

        String sound = "";
        if (FrameAndSoundChecks.makesSound(source)) {
            if (Files.isRegularFile(wav)) {
                FrameAndSoundChecks.Level level = FrameAndSoundChecks.level(wav);
                if (!(level.acRms >= MIN_AC_RMS)) {
                    throw new AssertionError(sketch.className + " plays sound, but its recording " + wav
                            + " is silent: " + level + " (at least " + MIN_AC_RMS + " RMS expected)\n" + run.logs());
                }
                sound = ", sound " + level;
            } else if (RECORDING_REQUIRED) {
                throw new AssertionError(sketch.className + " plays sound but left no recording " + wav + " (-D"
                        + RECORD_PROPERTY + ")\n" + run.logs());
            } else {
                sound = ", sound not checked (no recording: " + RECORD_PROPERTY + " not implemented yet)";
            }
        }
        System.out.printf(Locale.ROOT, "%s: %d frames in %.1f s (JVM and Xvfb start included), frame %s, "
                + "%.1f %% drawn, %.1f %% changed since frame %d%s; then %d input events (%s)%n", sketch.className,
                run.frames, run.seconds, png, 100 * drawn, 100 * changed, FRAMES / 2, sound, expectedEvents, input);
    }

    /** Whether a run ended only because Processing's OpenGL animator waited more than 5 s for setup to finish. */
    static boolean joglStartStarved(SketchHarness.Run run) {
        return run.stderr.contains("Waited 5000ms for") && run.stderr.contains("PSurfaceJOGL")
                && run.frames <= 0;
    }

    private static String loadAverage() {
        try {
            return Files.readString(Path.of("/proc/loadavg")).split(" ")[0];
        } catch (IOException | RuntimeException e) {
            return "unknown";
        }
    }

    private static final Pattern KEY_EQUALS = Pattern.compile("\\bkey\\s*==\\s*'(\\\\.|[^'\\\\])'");
    private static final Pattern KEY_RANGE = Pattern.compile(
            "\\bkey\\s*>=\\s*'([^'\\\\])'\\s*&&\\s*key\\s*<=\\s*'([^'\\\\])'");
    private static final Pattern KEY_CODE = Pattern.compile("\\bkeyCode\\s*==\\s*(UP|DOWN|LEFT|RIGHT)\\b");
    private static final Pattern MOUSE = Pattern.compile("\\bvoid\\s+mouse(Pressed|Dragged|Released)\\s*\\(");

    /**
     * The input a sketch reacts to, as a script for {@link SketchRunner#INPUT_PROPERTY}: every key its source
     * compares {@code key} or {@code keyCode} with (in the order they appear; both ends of a range such as
     * {@code key >= '1' && key <= '9'}), then the mouse if it has a mouse handler. The runner plays it after the
     * checked frames, so that the code behind every control runs too, and any exception it throws fails the test.
     *
     * @param source the code of all the sketch's tabs
     * @return the script, empty if the sketch takes no input
     */
    static String inputScript(String source) {
        List<String> items = new ArrayList<>();
        Matcher m = KEY_EQUALS.matcher(source);
        List<int[]> found = new ArrayList<>(); // {position, item kind, value}
        while (m.find()) {
            String c = m.group(1);
            char ch = c.length() == 1 ? c.charAt(0) : unescape(c.charAt(1));
            found.add(new int[] {m.start(), 'k', ch});
        }
        m = KEY_RANGE.matcher(source);
        while (m.find()) {
            found.add(new int[] {m.start(), 'k', m.group(1).charAt(0)});
            found.add(new int[] {m.start() + 1, 'k', m.group(2).charAt(0)});
        }
        m = KEY_CODE.matcher(source);
        while (m.find()) {
            int code;
            switch (m.group(1)) {
                case "UP": code = processing.core.PConstants.UP; break;
                case "DOWN": code = processing.core.PConstants.DOWN; break;
                case "LEFT": code = processing.core.PConstants.LEFT; break;
                default: code = processing.core.PConstants.RIGHT; break;
            }
            found.add(new int[] {m.start(), 'c', code});
        }
        found.sort(Comparator.comparingInt(f -> f[0]));
        for (int[] f : found) {
            String item = (char) f[1] + Integer.toString(f[2]);
            if (!items.contains(item)) {
                items.add(item);
            }
        }
        if (MOUSE.matcher(source).find()) {
            items.add("mouse");
        }
        return String.join(",", items);
    }

    private static char unescape(char c) {
        switch (c) {
            case 'n': return '\n';
            case 't': return '\t';
            case 'r': return '\r';
            case 'b': return '\b';
            default: return c; // \' and \\
        }
    }

    static String pdeSource(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            StringBuilder all = new StringBuilder();
            for (Path p : s.filter(p -> p.toString().endsWith(".pde")).sorted().collect(Collectors.toList())) {
                all.append(new String(Files.readAllBytes(p), StandardCharsets.UTF_8)).append('\n');
            }
            return all.toString();
        }
    }

    static void copyTree(Path from, Path to) throws IOException {
        try (Stream<Path> s = Files.walk(from)) {
            for (Path p : s.collect(Collectors.toList())) {
                Path target = to.resolve(from.relativize(p).toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(target);
                } else {
                    Files.copy(p, target, StandardCopyOption.REPLACE_EXISTING);
                }
            }
        }
    }

    static void deleteTree(Path root) throws IOException {
        if (!Files.exists(root)) {
            return;
        }
        try (Stream<Path> s = Files.walk(root)) {
            for (Path p : s.sorted(Comparator.reverseOrder()).collect(Collectors.toList())) {
                Files.delete(p);
            }
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }
}
