package tactus.audio;

import tactus.haptics.AvatarLink;

/**
 * Connects a {@link tactus.haptics.HapticLoop} in {@code Mode.AUDIO} to a {@link PhyUGen}'s avatar through an
 * {@link AvatarExchange}: the loop's position goes to the exchange (the audio thread applies it at its next
 * sample, through the avatar's EWMA) and the force the audio thread accumulated comes back with the number of
 * audio steps it covers, so the loop renders the exact mean force per step whatever the two rates and the
 * audio buffer size. Neither call waits for the audio thread, so the loop calls this link directly, with no
 * helper thread ({@link #neverWaits()}).
 *
 * <pre>
 * AvatarExchange exchange = new AvatarExchange();
 * ugen.attachAvatar("avatar", exchange);
 * HapticLoop loop = haptics.attach(new ExchangeAvatarLink(exchange));
 * loop.setMode(HapticLoop.Mode.AUDIO);
 * </pre>
 */
public final class ExchangeAvatarLink implements AvatarLink {
    private final AvatarExchange exchange;

    /**
     * Creates a link that hands the haptic loop the avatar force a {@link PhyUGen} accumulated.
     *
     * @param exchange the exchange that a {@link PhyUGen} was given with {@link PhyUGen#attachAvatar}; either
     *     force mode works (the link always hands the loop the sum and its step count)
     */
    public ExchangeAvatarLink(AvatarExchange exchange) {
        if (exchange == null) {
            throw new IllegalArgumentException("ExchangeAvatarLink: the exchange must not be null");
        }
        this.exchange = exchange;
    }

    /** The exchange this link talks through. */
    public AvatarExchange exchange() {
        return exchange;
    }

    /** Publishes the avatar's target position (model units) for the audio thread. */
    @Override
    public void setTarget(double x, double y, double z) {
        exchange.publishPosition(x, y, z);
    }

    /** Writes the force summed over the audio steps since the last take (model force units) into out[0..2]. */
    @Override
    public void takeForce(double[] out) {
        takeForceCounted(out);
    }

    /**
     * Writes the force summed over the audio steps since the last take into out[0..2] and returns how many steps
     * that is (0 when none ran or the audio thread was writing at that instant; the force then waits for the next
     * take).
     */
    @Override
    public long takeForceCounted(double[] out) {
        long n = exchange.takeForce(out);
        if (exchange.forceMode() == AvatarExchange.ForceMode.AVERAGE) {
            out[0] *= n;
            out[1] *= n;
            out[2] *= n;
        }
        return n;
    }

    /** True: both calls are lock-free, so the haptic loop needs no helper thread. */
    @Override
    public boolean neverWaits() {
        return true;
    }

    /** Does nothing: in audio mode the audio thread steps the model. */
    @Override
    public void step(int n) {
    }
}
