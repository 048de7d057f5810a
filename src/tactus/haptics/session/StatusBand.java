package tactus.haptics.session;

import processing.core.PApplet;

/**
 * The status line a haptic session draws at the bottom-left of the window: on a band whose colour says whether the
 * device is real, emulated or in trouble, whatever the sketch's transforms, camera and styles (all restored).
 *
 * <p>Not API: public only for the two sessions in {@code tactus.haptics}.
 */
public final class StatusBand {
    private StatusBand() {
    }

    /** Draws {@code text} on its band: red when {@code trouble}, slate for an emulator, green for a device. */
    public static void draw(PApplet app, String text, boolean trouble, boolean emulated) {
        boolean threeD = app.g.is3D();
        app.pushMatrix();
        app.pushStyle();
        app.resetMatrix();
        if (threeD) {
            app.hint(PApplet.DISABLE_DEPTH_TEST);
            app.camera();
        }
        app.textSize(13);
        app.textAlign(PApplet.LEFT, PApplet.BASELINE);
        app.noStroke();
        app.fill(trouble ? 0xE0A02020 : emulated ? 0xD0303848 : 0xD0205030);
        app.rect(0, app.height - 24, Math.min(app.width, app.textWidth(text) + 20), 24);
        app.fill(255);
        app.text(text, 10, app.height - 8);
        if (threeD) {
            app.hint(PApplet.ENABLE_DEPTH_TEST);
        }
        app.popStyle();
        app.popMatrix();
    }
}
