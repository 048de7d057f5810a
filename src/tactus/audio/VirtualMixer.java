package tactus.audio;

import javax.sound.sampled.AudioFormat;
import javax.sound.sampled.AudioSystem;
import javax.sound.sampled.DataLine;
import javax.sound.sampled.Line;
import javax.sound.sampled.LineUnavailableException;
import javax.sound.sampled.Mixer;
import javax.sound.sampled.SourceDataLine;

/**
 * A Java Sound mixer with no device behind it: its {@link VirtualSourceLine}s play signed PCM (8 or 16 bits,
 * little-endian, 1 or 2 channels, any rate) into nothing, in real time. It offers them only when no real mixer
 * can play the format, or when {@code javax.sound.sampled.SourceDataLine} names {@link VirtualMixerProvider}; see
 * there.
 */
final class VirtualMixer extends BareLine implements Mixer {
    /** The mixer's name, vendor, description and version. */
    static final Mixer.Info INFO = new Mixer.Info("Tactus virtual output", "Tactus",
            "Plays into nothing in real time (no sound card); records when -Dtactus.audio.record=<file.wav>",
            tactus.PhysicalModel.VERSION) {
    };
    private static final String DEFAULT_PROPERTY = "javax.sound.sampled.SourceDataLine";
    private static final AudioFormat[] FORMATS = {
        format(1, 16), format(2, 16), format(1, 8), format(2, 8)
    };
    private static final DataLine.Info SOURCE = new DataLine.Info(SourceDataLine.class, FORMATS,
            AudioSystem.NOT_SPECIFIED, AudioSystem.NOT_SPECIFIED);

    private static AudioFormat format(int channels, int bits) {
        return new AudioFormat(AudioFormat.Encoding.PCM_SIGNED, AudioSystem.NOT_SPECIFIED, bits, channels,
                channels * bits / 8, AudioSystem.NOT_SPECIFIED, false);
    }

    /** @return true when the standard property names this provider as the default source line. */
    static boolean namedByProperty() {
        String p = System.getProperty(DEFAULT_PROPERTY);
        if (p == null) {
            return false;
        }
        int hash = p.indexOf('#');
        String provider = (hash < 0 ? p : p.substring(0, hash)).trim();
        String mixer = hash < 0 ? "" : p.substring(hash + 1).trim();
        return provider.equals(VirtualMixerProvider.class.getName()) || (provider.isEmpty()
                && mixer.equals(INFO.getName()));
    }

    /** @return true when some other mixer can give a line matching {@code info}. */
    static boolean realMixerSupports(Line.Info info) {
        for (Mixer.Info mi : AudioSystem.getMixerInfo()) {
            if (INFO.equals(mi)) {
                continue;
            }
            try {
                if (AudioSystem.getMixer(mi).isLineSupported(info)) {
                    return true;
                }
            } catch (RuntimeException e) {
                // a broken provider: ignore it
            }
        }
        return false;
    }

    private static boolean offers(Line.Info info) {
        return info.matches(SOURCE) && (namedByProperty() || !realMixerSupports(info));
    }

    @Override
    public Mixer.Info getMixerInfo() {
        return INFO;
    }

    @Override
    public Line.Info[] getSourceLineInfo() {
        return new Line.Info[] {SOURCE};
    }

    @Override
    public Line.Info[] getTargetLineInfo() {
        return new Line.Info[0];
    }

    @Override
    public Line.Info[] getSourceLineInfo(Line.Info info) {
        return offers(info) ? new Line.Info[] {SOURCE} : new Line.Info[0];
    }

    @Override
    public Line.Info[] getTargetLineInfo(Line.Info info) {
        return new Line.Info[0];
    }

    @Override
    public boolean isLineSupported(Line.Info info) {
        return offers(info);
    }

    @Override
    public Line getLine(Line.Info info) throws LineUnavailableException {
        if (!info.matches(SOURCE)) {
            throw new IllegalArgumentException("Tactus virtual output: only source data lines of signed PCM, got "
                    + info);
        }
        AudioFormat f = new AudioFormat(44100f, 16, 2, true, false);
        if (info instanceof DataLine.Info) {
            for (AudioFormat asked : ((DataLine.Info) info).getFormats()) {
                if (asked.getSampleRate() != AudioSystem.NOT_SPECIFIED
                        && asked.getChannels() != AudioSystem.NOT_SPECIFIED) {
                    f = asked;
                    break;
                }
            }
        }
        return new VirtualSourceLine(SOURCE, f);
    }

    @Override
    public int getMaxLines(Line.Info info) {
        return info.matches(SOURCE) ? AudioSystem.NOT_SPECIFIED : 0;
    }

    @Override
    public Line[] getSourceLines() {
        return new Line[0];
    }

    @Override
    public Line[] getTargetLines() {
        return new Line[0];
    }

    @Override
    public void synchronize(Line[] lines, boolean maintainSync) {
        throw new IllegalArgumentException("Tactus virtual output: synchronisation is not supported");
    }

    @Override
    public void unsynchronize(Line[] lines) {
        throw new IllegalArgumentException("Tactus virtual output: synchronisation is not supported");
    }

    @Override
    public boolean isSynchronizationSupported(Line[] lines, boolean maintainSync) {
        return false;
    }

    @Override
    public Line.Info getLineInfo() {
        return new Line.Info(Mixer.class);
    }

    @Override
    public void open() {
    }

    @Override
    public void close() {
    }

    @Override
    public boolean isOpen() {
        return true;
    }
}
