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
        if (!namedByProperty()) { // a program that named the virtual output asked for it: nothing to say
            tellOnce(System.err);
        }
        return new VirtualSourceLine(SOURCE, f);
    }

    /** Whether the line saying that the sound goes nowhere was printed in this JVM. */
    private static final java.util.concurrent.atomic.AtomicBoolean TOLD = new java.util.concurrent.atomic.AtomicBoolean();

    /**
     * Prints, the first time in the JVM that a line of the virtual output is handed out, one line saying that the
     * sound goes nowhere and how to render a WAV instead.
     *
     * @return true if it printed now
     */
    static boolean tellOnce(java.io.PrintStream out) {
        if (!TOLD.compareAndSet(false, true)) {
            return false;
        }
        out.println(notice(System.getProperty(HeadlessRecording.PROPERTY)));
        out.flush();
        return true;
    }

    /**
     * The line of {@link #tellOnce}.
     *
     * @param record the value of {@value HeadlessRecording#PROPERTY}, or null
     */
    static String notice(String record) {
        String start = "Tactus audio: no sound device, so the sound plays into Tactus's virtual output";
        if (record != null && !record.trim().isEmpty()) {
            return start + " and is recorded to " + new java.io.File(record.trim()).getAbsolutePath() + " ("
                    + HeadlessRecording.PROPERTY + ")";
        }
        return start + " and goes nowhere. To hear it, render a WAV: run with -D" + HeadlessRecording.PROPERTY
                + "=out.wav to record this output, or render offline with tactus.audio.OfflineRenderer.renderToWav";
    }

    /** Lets a test see the line printed again. */
    static void forgetToldForTests() {
        TOLD.set(false);
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
