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

    /** {@return a new standard mass painter} */
    public static MassPainter masses() {
        return new Masses();
    }

    /** {@return a new standard arrow painter: a line with a two-stroke head a quarter of its length} */
    public static ArrowPainter arrows() {
        return new Arrows();
    }

    /** {@return a new standard link painter} */
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

    private static final class Arrows implements ArrowPainter {
        private static final float HEAD = 0.25f;
        private static final float SPREAD = 0.4f;   // half-width of the head over its length

        @Override
        public void arrow(PGraphics g, int index, matModuleType type, float x, float y, float z, float dx, float dy,
                          float dz, float weight, int argb) {
            g.stroke(argb);
            g.strokeWeight(weight);
            float ex = x + dx;
            float ey = y + dy;
            if (g.is3D()) {
                float ez = z + dz;
                float len = (float) Math.sqrt(dx * dx + dy * dy + dz * dz);
                if (!(len > 0)) {
                    return;
                }
                g.line(x, y, z, ex, ey, ez);
                // a side vector: the arrow crossed with z, or with x when the arrow is along z
                float sx = dy;
                float sy = -dx;
                float sz = 0;
                float sl = (float) Math.sqrt(sx * sx + sy * sy);
                if (sl < 1e-6f * len) {
                    sx = 0;
                    sy = dz;
                    sz = -dy;
                    sl = (float) Math.sqrt(sy * sy + sz * sz);
                }
                float k = SPREAD * HEAD * len / sl;
                float bx = ex - HEAD * dx;
                float by = ey - HEAD * dy;
                float bz = ez - HEAD * dz;
                g.line(ex, ey, ez, bx + k * sx, by + k * sy, bz + k * sz);
                g.line(ex, ey, ez, bx - k * sx, by - k * sy, bz - k * sz);
            } else {
                float len = (float) Math.sqrt(dx * dx + dy * dy);
                if (!(len > 0)) {
                    return;
                }
                g.line(x, y, ex, ey);
                float bx = ex - HEAD * dx;
                float by = ey - HEAD * dy;
                float k = SPREAD * HEAD;
                g.line(ex, ey, bx + k * dy, by - k * dx);
                g.line(ex, ey, bx - k * dy, by + k * dx);
            }
        }
    }
}
