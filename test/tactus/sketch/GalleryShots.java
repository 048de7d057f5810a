package tactus.sketch;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

/**
 * Makes the docs site's gallery: one picture of every example sketch at a fixed size, a copy of its source, and
 * the Markdown page that shows them, all under a build folder (never in the repository).
 * <p>
 * A sketch's picture is its last frame as {@link ExamplesTest} saved it ({@code <frames>/<Sketch>/frame.png})
 * when that frame is newer than every file of the sketch; otherwise the sketch is run here, headless under Xvfb,
 * the same way. The frame is scaled to fit {@value #WIDTH} x {@value #HEIGHT} pixels, centred on the frame's
 * background colour.
 * <p>
 * Run by {@code gradle site}: {@code GalleryShots <examples> <frames> <out>}, with the system property
 * {@value SketchHarness#CLASSPATH_PROPERTY} set as for the sketch tests.
 */
public final class GalleryShots {
    /** Width of every gallery picture, in pixels. */
    static final int WIDTH = 640;
    /** Height of every gallery picture, in pixels. */
    static final int HEIGHT = 400;
    /** Frames a sketch draws when it has to be run here: two seconds at 60 frames per second. */
    static final int FRAMES = 120;
    /** The longest one sketch may run here, in seconds. */
    static final double TIMEOUT_SECONDS = 180;
    /** The gallery page's file name, in the output folder. */
    static final String PAGE = "gallery.md";

    private static final Pattern FIRST_COMMENT = Pattern.compile("(?s)^\\s*/\\*+(.*?)\\*/");

    private GalleryShots() {
    }

    /**
     * Writes the gallery: pictures into {@code <out>/gallery/}, sources into {@code <out>/examples/} and the page
     * {@code <out>/gallery.md}.
     *
     * @param args the examples folder, the folder of the sketch tests' frames, the output folder
     * @throws IOException if a file cannot be read or written
     */
    public static void main(String[] args) throws IOException {
        if (args.length != 3) {
            System.err.println("usage: GalleryShots EXAMPLES_DIR FRAMES_DIR OUT_DIR");
            System.exit(2);
        }
        Path examples = Paths.get(args[0]);
        Path frames = Paths.get(args[1]);
        Path out = Paths.get(args[2]);
        List<Path> sketches = new ArrayList<>(SketchHarness.findSketches(examples));
        sketches.sort(Comparator.comparingInt((Path d) -> groupRank(examples.relativize(d)))
                .thenComparing(Path::toString));
        Files.createDirectories(out.resolve("gallery"));
        StringBuilder page = new StringBuilder();
        page.append("# Gallery\n\n")
            .append("Every example that comes with Tactus, as it looks after a few seconds with no one touching it")
            .append(" (no mouse, no keys, no Haply: the haptic ones run on the emulator, whose hand tours the")
            .append(" workspace on its own). Click a picture for the sketch's source. In Processing they are all")
            .append(" under *File > Examples > Contributed Libraries > Tactus*.\n\n")
            .append("These pictures are made when the site is built, by running each sketch headless.\n");
        String group = null;
        for (Path dir : sketches) {
            Path rel = examples.relativize(dir);
            String name = dir.getFileName().toString();
            String thisGroup = rel.getNameCount() > 1 ? rel.getName(0).toString() : "Examples";
            if (!thisGroup.equals(group)) {
                if (group != null) {
                    page.append("\n</div>\n");
                }
                group = thisGroup;
                page.append("\n## ").append(group).append("\n\n<div class=\"tactus-gallery\" markdown>\n");
            }
            BufferedImage frame = frameOf(dir, name, frames);
            String picture = "gallery/" + rel.toString().replace('/', '-').replace('\\', '-') + ".png";
            ImageIO.write(fit(frame, WIDTH, HEIGHT), "png", out.resolve(picture).toFile());
            String sourceFolder = "examples/" + rel.toString().replace('\\', '/');
            ExamplesTest.deleteTree(out.resolve(sourceFolder));
            Files.createDirectories(out.resolve(sourceFolder));
            try (Stream<Path> tabs = Files.list(dir)) {
                for (Path tab : (Iterable<Path>) tabs.filter(p -> p.toString().endsWith(".pde")).sorted()::iterator) {
                    Files.copy(tab, out.resolve(sourceFolder).resolve(tab.getFileName()));
                }
            }
            String mainTab = sourceFolder + "/" + name + ".pde";
            String summary = summary(new String(Files.readAllBytes(dir.resolve(name + ".pde")),
                    StandardCharsets.UTF_8), name);
            page.append("\n<figure markdown>\n[![").append(name).append("](").append(picture).append(")](")
                .append(mainTab).append(")\n<figcaption markdown>**[").append(name).append("](").append(mainTab)
                .append(")**: ").append(summary).append("</figcaption>\n</figure>\n");
            System.out.println("gallery: " + rel + " -> " + picture);
        }
        if (group != null) {
            page.append("\n</div>\n");
        }
        Files.write(out.resolve(PAGE), page.toString().getBytes(StandardCharsets.UTF_8));
        System.out.printf(Locale.ROOT, "gallery: %d examples, page %s%n", sketches.size(), out.resolve(PAGE));
    }

    /** Groups in the order a newcomer meets them; groups not listed come after, by name. */
    static final List<String> GROUP_ORDER = List.of("Basics", "Lesson", "Visuals", "Audio", "Haptics", "Haptics3D");

    private static int groupRank(Path rel) {
        int i = rel.getNameCount() > 1 ? GROUP_ORDER.indexOf(rel.getName(0).toString()) : -1;
        return i < 0 ? GROUP_ORDER.size() : i;
    }

    /** The sketch's last frame: the sketch tests' copy if it is up to date, else a fresh headless run. */
    private static BufferedImage frameOf(Path dir, String name, Path frames) throws IOException {
        Path saved = frames.resolve(name).resolve("frame.png");
        if (Files.isRegularFile(saved) && newerThanSources(saved, dir)) {
            BufferedImage img = ImageIO.read(saved.toFile());
            if (img != null) {
                return img;
            }
        }
        String classpath = SketchHarness.sketchClasspath();
        SketchHarness.JavaSketch sketch = SketchHarness.preprocess(dir);
        Path work = Files.createDirectories(frames.resolve(name));
        Path classes = SketchHarness.compile(sketch, work, classpath);
        Path sketchCopy = work.resolve("sketch");
        ExamplesTest.deleteTree(sketchCopy);
        ExamplesTest.copyTree(dir, sketchCopy);
        Path png = work.resolve("frame.png");   // where the sketch tests keep it: reused next time
        SketchHarness.Run run = SketchHarness.run(sketch.className, classes, classpath, FRAMES, png,
                TIMEOUT_SECONDS, sketchCopy, Map.of());
        try {
            SketchHarness.check(run, FRAMES);
        } catch (AssertionError first) {
            // A P3D sketch under software OpenGL can miss JOGL's 5 s animator wait on a loaded machine: one more try.
            System.out.println("gallery: " + name + " failed once, running it again: "
                    + first.getMessage().lines().findFirst().orElse(""));
            run = SketchHarness.run(sketch.className, classes, classpath, FRAMES, png, TIMEOUT_SECONDS, sketchCopy,
                    Map.of());
            SketchHarness.check(run, FRAMES);
        }
        System.out.printf(Locale.ROOT, "gallery: ran %s (%d frames in %.1f s)%n", name, run.frames, run.seconds);
        return run.image;
    }

    private static boolean newerThanSources(Path frame, Path sketchDir) throws IOException {
        FileTime made = Files.getLastModifiedTime(frame);
        try (Stream<Path> s = Files.walk(sketchDir)) {
            return s.filter(Files::isRegularFile).allMatch(p -> {
                try {
                    return Files.getLastModifiedTime(p).compareTo(made) < 0;
                } catch (IOException e) {
                    return false;
                }
            });
        }
    }

    /**
     * Scales an image to fit a box, keeping its proportions, centred on the colour of its top-left pixel.
     *
     * @param img    the image
     * @param width  the box width, in pixels
     * @param height the box height, in pixels
     * @return a new image of exactly that size
     */
    static BufferedImage fit(BufferedImage img, int width, int height) {
        double scale = Math.min((double) width / img.getWidth(), (double) height / img.getHeight());
        int w = (int) Math.round(img.getWidth() * scale);
        int h = (int) Math.round(img.getHeight() * scale);
        BufferedImage box = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = box.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_BICUBIC);
        g.setRenderingHint(RenderingHints.KEY_RENDERING, RenderingHints.VALUE_RENDER_QUALITY);
        g.setColor(new Color(img.getRGB(0, 0)));
        g.fillRect(0, 0, width, height);
        g.drawImage(img, (width - w) / 2, (height - h) / 2, w, h, null);
        g.dispose();
        return box;
    }

    /**
     * The first sentence of the sketch's opening comment, without the leading {@code Name:}; or a plain
     * fallback when the sketch has no such comment.
     *
     * @param source the main tab's code
     * @param name   the sketch name
     * @return one sentence of Markdown-safe text
     */
    static String summary(String source, String name) {
        Matcher m = FIRST_COMMENT.matcher(source);
        if (!m.find()) {
            return "the " + name + " example.";
        }
        String text = m.group(1).replaceAll("(?m)^\\s*\\*+ ?", " ").replaceAll("\\s+", " ").trim();
        if (text.startsWith(name + ":")) {
            text = text.substring(name.length() + 1).trim();
        }
        int end = firstSentenceEnd(text);
        String sentence = end < 0 ? text : text.substring(0, end + 1);
        sentence = sentence.replace('<', ' ').replace('>', ' ').replace('|', ' ');
        return sentence.isEmpty() ? "the " + name + " example." : sentence;
    }

    private static int firstSentenceEnd(String text) {
        for (int i = 0; i < text.length() - 1; i++) {
            if (text.charAt(i) == '.' && text.charAt(i + 1) == ' ' && !text.startsWith("e.g", Math.max(0, i - 3))) {
                return i;
            }
        }
        return text.endsWith(".") ? text.length() - 1 : -1;
    }
}
