package tactus.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The site crawler on small hand-made sites: it must find what is broken and pass what is whole. */
class SiteCheckTest {
    @TempDir
    Path dir;

    private Path write(String rel, String text) throws IOException {
        Path p = dir.resolve(rel);
        Files.createDirectories(p.getParent());
        Files.write(p, text.getBytes(StandardCharsets.UTF_8));
        return p;
    }

    private void sketch(String group, String name) throws IOException {
        write("examples/" + group + "/" + name + "/" + name + ".pde", "void setup() {}\n");
    }

    @Test
    void aWholeSitePasses() throws IOException {
        write("site/index.html", "<a href=\"a.html#top\">a</a> <img src='img/p.png'> <a href=\"https://x.org/\">x</a>"
                + " <a href=\"#here\">here</a> <a href=\"mailto:a@b\">m</a> <a href=\"sub/\">sub</a>");
        write("site/a.html", "<a href=\"index.html?q=1\">back</a> <a href=\"sub/b%20c.html\">b</a>");
        write("site/img/p.png", "png");
        write("site/sub/index.html", "<a href=\"../a.html\">a</a>");
        write("site/sub/b c.html", "<link href=\"../img/p.png\">");
        SiteCheck.Result r = SiteCheck.crawl(dir.resolve("site"));
        assertEquals(List.of(), r.broken);
        assertEquals(4, r.pages.size(), "pages reached: " + r.pages);
    }

    @Test
    void brokenLinksAndImagesAreFoundOnPagesReachedByLinks() throws IOException {
        write("site/index.html", "<a href=\"a.html\">a</a> <img src=\"missing.png\">");
        write("site/a.html", "<a href=\"gone.html#x\">gone</a> <a href=\"../../outside.html\">out</a>"
                + " <a href=\"folder/\">folder without index</a>");
        Files.createDirectories(dir.resolve("site/folder"));
        write("outside.html", "x");
        SiteCheck.Result r = SiteCheck.crawl(dir.resolve("site"));
        assertEquals(4, r.broken.size(), "broken: " + r.broken);
        assertTrue(r.broken.get(0).contains("missing.png"), r.broken.toString());
        assertTrue(r.broken.stream().anyMatch(b -> b.startsWith("a.html: gone.html#x")), r.broken.toString());
        assertTrue(r.broken.stream().anyMatch(b -> b.contains("outside the site")), r.broken.toString());
        assertTrue(r.broken.stream().anyMatch(b -> b.contains("folder/")), r.broken.toString());
    }

    @Test
    void aSiteWithoutFrontPageIsBroken() {
        assertEquals(1, SiteCheck.crawl(dir).broken.size());
    }

    @Test
    void theGalleryMustShowEveryExample() throws IOException {
        sketch("Basics", "One");
        sketch("Audio", "Two");
        sketch("Audio", "Three");
        write("examples/Audio/NotASketch/Other.pde", "");   // a folder without its own .pde is no sketch
        write("site/gallery/Basics-One.png", "png");
        write("site/gallery/Audio-Two.png", "png");
        String one = "<img src=\"gallery/Basics-One.png\"><a href=\"x\">One</a>";
        String two = "<img src=\"gallery/Audio-Two.png\"><a href=\"x\">Two</a>";
        write("site/gallery.html", one + two);
        List<String> problems = SiteCheck.checkGallery(dir.resolve("site"), dir.resolve("examples"));
        assertEquals(2, problems.size(), problems.toString());
        assertTrue(problems.get(0).contains("2 pictures for 3 examples"), problems.toString());
        assertTrue(problems.get(1).contains("Three"), problems.toString());

        write("site/gallery/Audio-Three.png", "png");
        write("site/gallery.html", one + two + "<img src=\"gallery/Audio-Three.png\"><a href=\"x\">Three</a>");
        assertEquals(List.of(), SiteCheck.checkGallery(dir.resolve("site"), dir.resolve("examples")));

        Files.delete(dir.resolve("site/gallery/Audio-Three.png"));   // a picture named on the page but missing
        assertEquals(1, SiteCheck.checkGallery(dir.resolve("site"), dir.resolve("examples")).size());
    }
}
