package tactus.demo;

import tactus.haptics.HapticLoop;

/**
 * How the demo maps the Haply's handle (metres, device coordinates: x from motor 1 towards motor 2, y away
 * from the motors) to the model (units) and the avatar's force back to newtons, as the haptic loop does:
 * {@code model = (-alpha x + ox, alpha y + oy)} (x mirrored, the loop's default, as the paper's sketches draw
 * the device seen from the user) and {@code device force = (-beta Fx, beta Fy)}.
 *
 * <p>The string of {@link PluckScene} (y = 0, x from 0 to its length) is centred on the device point
 * ({@link #CENTRE_X}, {@link #STRING_Y}): with {@link #ALPHA} = 25 units per metre it is 12.4 cm long.
 */
public final class DeviceMapping {
    /** Model units per metre of handle motion. */
    public static final double ALPHA = 25;
    /**
     * Newtons per model force unit. The haptic loop takes the avatar force averaged over the audio steps of
     * a tick ({@code AvatarExchange.ForceMode.AVERAGE}), so this does not depend on the two rates.
     */
    public static final double BETA = 1500;
    /** Device x of the string's middle, metres (halfway between the motors of a 2018 Haply). */
    public static final double CENTRE_X = 0.01;
    /** Device y of the string, metres. */
    public static final double STRING_Y = 0.08;

    private final double ox;
    private final double oy;

    /** The mapping of the demo's scene. */
    public DeviceMapping() {
        ox = PluckScene.length() / 2 + ALPHA * CENTRE_X;
        oy = -ALPHA * STRING_Y;
    }

    /** Configures a haptic loop with this mapping (before it starts). */
    public void configure(HapticLoop loop) {
        loop.setPositionGain(ALPHA);
        loop.setForceGain(BETA);
        loop.setMirrorX(true);
        loop.setOrigin(ox, oy, 0);
    }

    /** @return the model x of device x (metres). */
    public double modelX(double deviceX) {
        return -ALPHA * deviceX + ox;
    }

    /** @return the model y of device y (metres). */
    public double modelY(double deviceY) {
        return ALPHA * deviceY + oy;
    }

    /** @return the device x (metres) of model x. */
    public double deviceX(double modelX) {
        return (ox - modelX) / ALPHA;
    }

    /** @return the device y (metres) of model y. */
    public double deviceY(double modelY) {
        return (modelY - oy) / ALPHA;
    }
}
