package tactus.site;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URLDecoder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * Crawls a built docs site from its front page and reports every broken local link or image, and whether the
 * gallery page shows a picture of every example sketch.
 * <p>
 * A local link is any {@code href} or {@code src} that is not an absolute URL ({@code http:}, {@code mailto:},
 * ...) or a bare fragment; it is broken when the file it names (its query and fragment removed) does not exist in
 * the site, or names a folder without {@code index.html}. Every HTML page reached is crawled in turn, the
 * Javadoc reference included. Run by {@code gradle site}: {@code SiteCheck <site> <examples>}; exit status 1
 * with one line per problem.
 */
public final class SiteCheck {
    /** The gallery page, relative to the site's root. */
    static final String GALLERY = "gallery.html";

    private static final Pattern LINK = Pattern.compile("(?i)\\b(?:href|src)\\s*=\\s*(\"([^\"]*)\"|'([^']*)')");
    private static final Pattern SCHEME = Pattern.compile("^[a-zA-Z][a-zA-Z0-9+.-]*:");
    private static final Pattern GALLERY_IMAGE = Pattern.compile("(?i)<img\\b[^>]*\\bsrc\\s*=\\s*\"(gallery/[^\"]+)\"");

    private SiteCheck() {
    }

    /** What a crawl found. */
    static final class Result {
        /** Pages crawled. */
        final Set<Path> pages = new LinkedHashSet<>();
        /** One line per broken link: the page, then the link. */
        final List<String> broken = new ArrayList<>();
        /** Local links checked, pages and other files together. */
        int links;
    }

    /**
     * Crawls the site from {@code index.html}, following every local link to an HTML page.
     *
     * @param site the site's root folder
     * @return the pages crawled and the broken links found
     */
    static Result crawl(Path site) {
        Result r = new Result();
        Path root = site.toAbsolutePath().normalize();
        Deque<Path> todo = new ArrayDeque<>();
        Path start = root.resolve("index.html");
        if (!Files.isRegularFile(start)) {
            r.broken.add("the site has no front page " + start);
            return r;
        }
        todo.add(start);
        r.pages.add(start);
        while (!todo.isEmpty()) {
            Path page = todo.poll();
            for (String link : links(read(page))) {
                Path target = target(page, link);
                if (target == null) {
                    continue;
                }
                r.links++;
                if (!target.startsWith(root)) {
                    r.broken.add(root.relativize(page) + ": " + link + " (outside the site)");
                    continue;
                }
                if (Files.isDirectory(target)) {
                    target = target.resolve("index.html");
                }
                if (!Files.isRegularFile(target)) {
                    r.broken.add(root.relativize(page) + ": " + link);
                    continue;
                }
                String name = target.getFileName().toString().toLowerCase(Locale.ROOT);
                if ((name.endsWith(".html") || name.endsWith(".htm")) && r.pages.add(target)) {
                    todo.add(target);
                }
            }
        }
        return r;
    }

    /** Every href and src value of a page, in order. */
    static List<String> links(String html) {
        List<String> out = new ArrayList<>();
        Matcher m = LINK.matcher(html);
        while (m.find()) {
            String v = m.group(2) != null ? m.group(2) : m.group(3);
            out.add(v.replace("&amp;", "&").trim());
        }
        return out;
    }

    /** The file a local link names, or null when the link is not local (a URL, a bare fragment, empty). */
    static Path target(Path page, String link) {
        if (link.isEmpty() || link.startsWith("#") || link.startsWith("//") || SCHEME.matcher(link).find()) {
            return null;
        }
        String path = link;
        int cut = indexOfAny(path, '#', '?');
        if (cut >= 0) {
            path = path.substring(0, cut);
        }
        if (path.isEmpty()) {
            return null;
        }
        path = URLDecoder.decode(path.replace("+", "%2B"), StandardCharsets.UTF_8);
        return page.getParent().resolve(path).normalize();
    }

    private static int indexOfAny(String s, char a, char b) {
        int i = s.indexOf(a);
        int j = s.indexOf(b);
        return i < 0 ? j : j < 0 ? i : Math.min(i, j);
    }

    /**
     * The example sketches: folders {@code Name} holding {@code Name.pde}, at any depth.
     *
     * @param examples the examples folder
     * @return their names, sorted
     */
    static Set<String> sketches(Path examples) {
        try (Stream<Path> s = Files.walk(examples)) {
            return s.filter(Files::isDirectory)
                    .filter(d -> d.getFileName() != null && Files.isRegularFile(d.resolve(d.getFileName() + ".pde")))
                    .map(d -> d.getFileName().toString())
                    .collect(Collectors.toCollection(TreeSet::new));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Checks that the gallery page shows one existing picture per example and names each example.
     *
     * @param site     the site's root folder
     * @param examples the examples folder
     * @return one line per problem, empty when the gallery is complete
     */
    static List<String> checkGallery(Path site, Path examples) {
        List<String> problems = new ArrayList<>();
        Path gallery = site.resolve(GALLERY);
        Set<String> names = sketches(examples);
        if (!Files.isRegularFile(gallery)) {
            problems.add("no gallery page " + gallery);
            return problems;
        }
        String html = read(gallery);
        Matcher m = GALLERY_IMAGE.matcher(html);
        Set<String> pictures = new HashSet<>();
        while (m.find()) {
            if (Files.isRegularFile(site.resolve(m.group(1)))) {
                pictures.add(m.group(1));
            }
        }
        if (pictures.size() != names.size()) {
            problems.add("the gallery shows " + pictures.size() + " pictures for " + names.size() + " examples in "
                    + examples);
        }
        for (String name : names) {
            if (!html.contains(">" + name + "<")) {
                problems.add("the gallery does not name the example " + name);
            }
        }
        return problems;
    }

    private static String read(Path p) {
        try {
            return new String(Files.readAllBytes(p), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Crawls the site and checks the gallery; prints a summary, and exits with status 1 if anything is wrong.
     *
     * @param args the site folder, then the examples folder
     */
    public static void main(String[] args) {
        if (args.length != 2) {
            System.err.println("usage: SiteCheck SITE_DIR EXAMPLES_DIR");
            System.exit(2);
        }
        Path site = Paths.get(args[0]);
        Path examples = Paths.get(args[1]);
        Result r = crawl(site);
        List<String> problems = new ArrayList<>();
        r.broken.forEach(b -> problems.add("broken link: " + b));
        problems.addAll(checkGallery(site, examples));
        System.out.printf(Locale.ROOT, "site check: %d pages crawled, %d local links, %d broken; gallery of %d "
                + "examples%n", r.pages.size(), r.links, r.broken.size(), sketches(examples).size());
        problems.forEach(p -> System.out.println("site check: " + p));
        if (!problems.isEmpty()) {
            System.exit(1);
        }
    }
}
