package tactus.audio;

import java.io.File;
import java.io.IOException;
import java.io.RandomAccessFile;
import javax.sound.sampled.AudioFormat;

/**
 * The WAV file that a headless output records to when the system property {@value #PROPERTY} names one
 * ({@code -Dtactus.audio.record=out.wav}; a relative path is taken from the JVM's working directory).
 *
 * <p>Both headless outputs record through it: the {@link VirtualMixerProvider virtual sound line} and the
 * {@link SilentAudioOut silent output} of {@link LineOut}. The first of them to play claims the file; it is created
 * (or truncated) then, with the output's format (16-bit or 8-bit PCM, 1 or 2 channels, the output's rate), and
 * every byte the output plays is appended, in real time. The header's sizes are rewritten after every write, so
 * the file is a valid WAV at all times, even when the JVM is halted without running shutdown hooks. A second
 * output in the same JVM does not record (one file per run). Without the property nothing is recorded. A file
 * that cannot be written prints one line on standard error and the output plays on without recording.
 */
public final class HeadlessRecording {
    /** The system property naming the WAV file to record to. */
    public static final String PROPERTY = "tactus.audio.record";
    private static final Object CLAIM = new Object();
    private static boolean claimed;

    private final RandomAccessFile file;
    private final File path;
    private long dataBytes;
    private boolean failed;

    private HeadlessRecording(File path, RandomAccessFile file) {
        this.path = path;
        this.file = file;
    }

    /**
     * Claims the run's recording for an output that plays {@code format}.
     *
     * @return the recording, or null when the property is not set, another output already claimed it, the format
     *     is not 8- or 16-bit signed PCM, or the file cannot be created (said on standard error)
     */
    static HeadlessRecording claim(AudioFormat format) {
        String name = System.getProperty(PROPERTY);
        if (name == null || name.trim().isEmpty()) {
            return null;
        }
        synchronized (CLAIM) {
            if (claimed) {
                return null;
            }
            claimed = true;
        }
        int bits = format.getSampleSizeInBits();
        File path = new File(name.trim());
        if (!AudioFormat.Encoding.PCM_SIGNED.equals(format.getEncoding()) || (bits != 8 && bits != 16)
                || (bits == 16 && format.isBigEndian())) {
            System.err.println("Tactus audio: cannot record " + format + " to " + path + " (" + PROPERTY
                    + "): only 8- or 16-bit little-endian signed PCM");
            return null;
        }
        try {
            File parent = path.getAbsoluteFile().getParentFile();
            if (parent != null) {
                parent.mkdirs();
            }
            RandomAccessFile f = new RandomAccessFile(path, "rw");
            f.setLength(0);
            HeadlessRecording r = new HeadlessRecording(path, f);
            r.writeHeader(format);
            return r;
        } catch (IOException e) {
            System.err.println("Tactus audio: cannot record to " + path + " (" + PROPERTY + "): " + e.getMessage());
            return null;
        }
    }

    /** Forgets that the run's recording was claimed, so that a test can record again. */
    static void releaseClaimForTests() {
        synchronized (CLAIM) {
            claimed = false;
        }
    }

    /** @return the file recorded to. */
    File file() {
        return path;
    }

    private void writeHeader(AudioFormat format) throws IOException {
        int channels = format.getChannels();
        int bits = format.getSampleSizeInBits();
        int rate = Math.round(format.getSampleRate());
        int blockAlign = channels * bits / 8;
        byte[] h = new byte[44];
        put(h, 0, "RIFF");
        le32(h, 4, 36);
        put(h, 8, "WAVE");
        put(h, 12, "fmt ");
        le32(h, 16, 16);
        le16(h, 20, 1);
        le16(h, 22, channels);
        le32(h, 24, rate);
        le32(h, 28, rate * blockAlign);
        le16(h, 32, blockAlign);
        le16(h, 34, bits);
        put(h, 36, "data");
        le32(h, 40, 0);
        file.write(h);
    }

    /**
     * Appends played bytes (already in the recording's format, 8-bit samples signed as Java Sound gives them) and
     * rewrites the header's sizes. Called by the output's device thread, never by the audio graph.
     */
    synchronized void write(byte[] b, int off, int len, boolean eightBit) {
        if (failed || len <= 0) {
            return;
        }
        try {
            file.seek(44 + dataBytes);
            if (eightBit) {
                // WAV stores 8-bit samples unsigned
                byte[] u = new byte[len];
                for (int i = 0; i < len; i++) {
                    u[i] = (byte) (b[off + i] + 128);
                }
                file.write(u);
            } else {
                file.write(b, off, len);
            }
            dataBytes += len;
            byte[] size = new byte[4];
            le32(size, 0, (int) Math.min(0xFFFFFFFFL, 36 + dataBytes));
            file.seek(4);
            file.write(size);
            le32(size, 0, (int) Math.min(0xFFFFFFFFL, dataBytes));
            file.seek(40);
            file.write(size);
        } catch (IOException e) {
            failed = true;
            System.err.println("Tactus audio: recording to " + path + " stopped: " + e.getMessage());
        }
    }

    /** Appends float frames (interleaved per channel arrays), converted to 16-bit PCM and clipped to [-1, 1]. */
    void writeFloats(float[] left, float[] right, int frames, byte[] scratch) {
        int ch = right == null ? 1 : 2;
        int k = 0;
        for (int i = 0; i < frames; i++) {
            k = pcm16(scratch, k, left[i]);
            if (ch == 2) {
                k = pcm16(scratch, k, right[i]);
            }
        }
        write(scratch, 0, k, false);
    }

    private static int pcm16(byte[] b, int k, float v) {
        float c = Float.isNaN(v) ? 0 : Math.max(-1f, Math.min(1f, v));
        int s = Math.round(c * 32767f);
        b[k] = (byte) s;
        b[k + 1] = (byte) (s >> 8);
        return k + 2;
    }

    /** Closes the file; later writes are ignored. */
    synchronized void close() {
        failed = true;
        try {
            file.close();
        } catch (IOException e) {
            // nothing more to write
        }
    }

    private static void put(byte[] b, int at, String s) {
        for (int i = 0; i < 4; i++) {
            b[at + i] = (byte) s.charAt(i);
        }
    }

    private static void le16(byte[] b, int at, int v) {
        b[at] = (byte) v;
        b[at + 1] = (byte) (v >> 8);
    }

    private static void le32(byte[] b, int at, int v) {
        le16(b, at, v);
        le16(b, at + 2, v >> 16);
    }
}
