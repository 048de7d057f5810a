package tactus.render;

/** Packed-ARGB colour arithmetic and argument checks shared by the styles. */
final class Colors {
    private Colors() {
    }

    static int argb(int r, int g, int b, int a) {
        return (a << 24) | (r << 16) | (g << 8) | b;
    }

    /** Linear blend of two packed ARGB colours, channel by channel, rounded; {@code t} in 0..1. */
    static int lerp(int from, int to, float t) {
        int a = mix(from >>> 24, to >>> 24, t);
        int r = mix((from >> 16) & 0xFF, (to >> 16) & 0xFF, t);
        int g = mix((from >> 8) & 0xFF, (to >> 8) & 0xFF, t);
        int b = mix(from & 0xFF, to & 0xFF, t);
        return argb(r, g, b, a);
    }

    private static int mix(int x, int y, float t) {
        int v = Math.round(x + (y - x) * t);
        return v < 0 ? 0 : Math.min(v, 255);
    }

    static void checkChannels(String op, int r, int g, int b, int a) {
        checkChannel(op, "red", r);
        checkChannel(op, "green", g);
        checkChannel(op, "blue", b);
        checkChannel(op, "alpha", a);
    }

    private static void checkChannel(String op, String name, int v) {
        if (v < 0 || v > 255) {
            throw new IllegalArgumentException(op + ": " + name + " must be in 0..255, got " + v);
        }
    }

    static void checkSize(String op, String name, float v) {
        if (!(v >= 0) || !Float.isFinite(v)) {
            throw new IllegalArgumentException(op + ": " + name + " must be finite and >= 0, got " + v);
        }
    }
}
