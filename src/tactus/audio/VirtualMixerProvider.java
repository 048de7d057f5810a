package tactus.audio;

import javax.sound.sampled.Mixer;
import javax.sound.sampled.spi.MixerProvider;

/**
 * Registers Tactus's {@link VirtualMixer} with Java Sound (through {@code META-INF/services}), so that
 * {@code Minim.getLineOut()} and {@code AudioSystem.getSourceDataLine(...)} work on a machine with no sound card.
 *
 * <p>The virtual mixer offers its output line only when no other mixer can play the requested format, or when the
 * standard Java Sound property {@code javax.sound.sampled.SourceDataLine} names it
 * ({@code -Djavax.sound.sampled.SourceDataLine=tactus.audio.VirtualMixerProvider}, optionally followed by
 * {@code #Tactus virtual output}); a machine with a sound card therefore keeps playing through it. The line
 * consumes what it is given at the pace of the format's frame rate, like a device (so a UGen graph runs in real
 * time), discards it, and records it to a WAV file when {@value HeadlessRecording#PROPERTY} is set
 * (see {@link HeadlessRecording}).
 */
public final class VirtualMixerProvider extends MixerProvider {
    private static final VirtualMixer MIXER = new VirtualMixer();

    /** Creates the provider; Java Sound does this through the service loader. */
    public VirtualMixerProvider() {
    }

    @Override
    public Mixer.Info[] getMixerInfo() {
        return new Mixer.Info[] {VirtualMixer.INFO};
    }

    @Override
    public Mixer getMixer(Mixer.Info info) {
        if (info == null || VirtualMixer.INFO.equals(info)) {
            return MIXER;
        }
        throw new IllegalArgumentException("VirtualMixerProvider: no mixer " + info);
    }
}
