package tactus.render;

import processing.core.PConstants;
import processing.core.PGraphics;
import tactus.linkModuleType;
import tactus.matModuleType;

/**
 * The default painters: spheres and 3D lines in a 3D target (P3D), discs and lines orthographically projected on
 * the x-y plane in a 2D target (JAVA2D, P2D). Each sets the fill, stroke and stroke weight only when they change,
 * because a JAVA2D target allocates a colour object on every {@code fill()} and {@code stroke()} call.
 */
public final class StandardPainters {
    private StandardPainters() {
    }

    /** @return a new standard mass painter. */
    public static MassPainter masses() {
        return new Masses();
    }

    /** @return a new standard link painter. */
    public static LinkPainter links() {
        return new Links();
    }

    private static final class Masses implements MassPainter {
        private boolean threeD;
        private int fill;
        private boolean fillSet;

        @Override
        public void begin(PGraphics g, int count) {
            threeD = g.is3D();
            fillSet = false;
            g.noStroke();
            if (threeD) {
                // The paper engine's level of detail: finer spheres for small models.
                if (count < 100) {
                    g.sphereDetail(30);
                } else if (count < 1000) {
                    g.sphereDetail(15);
                } else if (count < 10000) {
                    g.sphereDetail(5);
                }
            } else {
                g.ellipseMode(PConstants.CENTER);
            }
        }

        @Override
        public void mass(PGraphics g, int index, matModuleType type, float x, float y, float z, float radius,
                         int argb) {
            if (!fillSet || argb != fill) {
                g.fill(argb);
                fill = argb;
                fillSet = true;
            }
            if (threeD) {
                g.pushMatrix();
                g.translate(x, y, z);
                g.sphere(radius);
                g.popMatrix();
            } else {
                float d = 2 * radius;
                g.ellipse(x, y, d, d);
            }
        }
    }

    private static final class Links implements LinkPainter {
        private boolean threeD;
        private int stroke;
        private float weight;
        private boolean set;

        @Override
        public void begin(PGraphics g, int count) {
            threeD = g.is3D();
            set = false;
            g.noFill();
        }

        @Override
        public void link(PGraphics g, int index, linkModuleType type, float x1, float y1, float z1, float x2,
                         float y2, float z2, float w, int argb) {
            if (!set || argb != stroke) {
                g.stroke(argb);
                stroke = argb;
            }
            if (!set || w != weight) {
                g.strokeWeight(w);
                weight = w;
            }
            set = true;
            if (threeD) {
                g.line(x1, y1, z1, x2, y2, z2);
            } else {
                g.line(x1, y1, x2, y2);
            }
        }
    }
}
