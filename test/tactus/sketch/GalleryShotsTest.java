package tactus.sketch;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;

import org.junit.jupiter.api.Test;

/** The gallery's picture fitting and captions (the pictures themselves are made by gradle site). */
class GalleryShotsTest {
    @Test
    void everyFrameIsFittedToTheSameSizeOnItsBackground() {
        for (int[] size : new int[][] {{800, 450}, {900, 500}, {800, 600}, {200, 900}}) {
            BufferedImage img = new BufferedImage(size[0], size[1], BufferedImage.TYPE_INT_RGB);
            for (int y = 0; y < size[1]; y++) {
                for (int x = 0; x < size[0]; x++) {
                    img.setRGB(x, y, 0x102030);
                }
            }
            img.setRGB(size[0] / 2, size[1] / 2, 0xffffff);
            BufferedImage fitted = GalleryShots.fit(img, GalleryShots.WIDTH, GalleryShots.HEIGHT);
            assertEquals(GalleryShots.WIDTH, fitted.getWidth());
            assertEquals(GalleryShots.HEIGHT, fitted.getHeight());
            assertEquals(0x102030, fitted.getRGB(0, 0) & 0xffffff, "corner of " + size[0] + "x" + size[1]);
            assertEquals(0x102030, fitted.getRGB(GalleryShots.WIDTH - 1, GalleryShots.HEIGHT - 1) & 0xffffff);
        }
    }

    @Test
    void theCaptionIsTheFirstSentenceOfTheOpeningComment() {
        String src = "/*\n * Rope: a rope of 40 masses, e.g. a chain. It swings.\n * More text.\n */\nvoid setup() {}\n";
        assertEquals("a rope of 40 masses, e.g. a chain.", GalleryShots.summary(src, "Rope"));
        assertEquals("a <b> c.".replace('<', ' ').replace('>', ' '),
                GalleryShots.summary("/** X: a <b> c. d */", "X"));
        assertEquals("the Bare example.", GalleryShots.summary("void setup() {}", "Bare"));
    }
}
