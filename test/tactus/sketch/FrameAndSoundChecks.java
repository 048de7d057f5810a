package tactus.sketch;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.regex.Pattern;

/**
 * What the example tests measure on a sketch's output: how much of a frame is drawn (not background), how much
 * changed between two frames, and how loud a recorded WAV file is.
 */
public final class FrameAndSoundChecks {

    /** Source text that means a sketch plays sound: a {@code PhyUGen}, or Minim's line out. */
    private static final Pattern MAKES_SOUND = Pattern.compile("\\bPhyUGen\\b|\\bgetLineOut\\b|\\bLineOut\\b");

    private FrameAndSoundChecks() {
    }

    /**
     * The share of pixels that differ from the most common colour (the background, in a sketch's frame). 0 for a
     * uniform image; a frame with a few words of text on it reaches about 1 %.
     *
     * @param img the image
     * @return the share, 0 to 1
     */
    public static double drawnShare(BufferedImage img) {
        Map<Integer, Integer> counts = new HashMap<>();
        int w = img.getWidth();
        int h = img.getHeight();
        int best = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int n = counts.merge(img.getRGB(x, y) & 0xFFFFFF, 1, Integer::sum);
                best = Math.max(best, n);
            }
        }
        long total = (long) w * h;
        return total == 0 ? 0 : (double) (total - best) / total;
    }

    /**
     * The share of pixels where two images of the same size differ by more than {@code tolerance} in some colour
     * channel (0 to 255).
     *
     * @param a         one image
     * @param b         the other, of the same size
     * @param tolerance the largest channel difference still counted as equal
     * @return the share, 0 to 1
     * @throws IllegalArgumentException if the sizes differ
     */
    public static double changedShare(BufferedImage a, BufferedImage b, int tolerance) {
        if (a.getWidth() != b.getWidth() || a.getHeight() != b.getHeight()) {
            throw new IllegalArgumentException("changedShare: sizes differ: " + a.getWidth() + "x" + a.getHeight()
                    + " and " + b.getWidth() + "x" + b.getHeight());
        }
        long changed = 0;
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                int p = a.getRGB(x, y);
                int q = b.getRGB(x, y);
                for (int shift = 0; shift <= 16; shift += 8) {
                    if (Math.abs(((p >> shift) & 0xFF) - ((q >> shift) & 0xFF)) > tolerance) {
                        changed++;
                        break;
                    }
                }
            }
        }
        return (double) changed / ((long) a.getWidth() * a.getHeight());
    }

    /**
     * Whether a sketch's source plays sound: it mentions {@code PhyUGen}, {@code getLineOut} or {@code LineOut}.
     *
     * @param pdeSource the code of all the sketch's tabs
     * @return true if it does
     */
    public static boolean makesSound(String pdeSource) {
        return MAKES_SOUND.matcher(pdeSource).find();
    }

    /** The level of a recorded sound. */
    public static final class Level {
        /** Frames (samples per channel) in the file. */
        public final long frames;
        /** Sample rate, in hertz. */
        public final int sampleRate;
        /** Root mean square of all samples after removing each channel's mean (DC), full scale = 1. */
        public final double acRms;
        /** Largest absolute sample, full scale = 1. */
        public final double peak;

        Level(long frames, int sampleRate, double acRms, double peak) {
            this.frames = frames;
            this.sampleRate = sampleRate;
            this.acRms = acRms;
            this.peak = peak;
        }

        /** @return the AC RMS in dB relative to full scale (-Infinity for silence). */
        public double acRmsDbfs() {
            return 20 * Math.log10(acRms);
        }

        @Override
        public String toString() {
            return String.format(java.util.Locale.ROOT, "%d frames at %d Hz, AC RMS %.3g (%.1f dBFS), peak %.3g",
                    frames, sampleRate, acRms, acRmsDbfs(), peak);
        }
    }

    /**
     * Reads a RIFF/WAVE file of 8- or 16-bit PCM or 32-bit IEEE float samples (what {@code tactus.audio.WavWriter}
     * and the headless audio output write) and measures its level. The mean of each channel is removed first:
     * a constant offset is not sound.
     *
     * @param wav the file
     * @return its level
     * @throws IllegalArgumentException if it is not such a file
     */
    public static Level level(Path wav) {
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(wav);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        ByteBuffer b = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
        if (bytes.length < 12 || b.getInt(0) != 0x46464952 || b.getInt(8) != 0x45564157) {
            throw new IllegalArgumentException(wav + " is not a RIFF/WAVE file");
        }
        int format = -1;
        int channels = 0;
        int rate = 0;
        int bits = 0;
        int pos = 12;
        while (pos + 8 <= bytes.length) {
            int id = b.getInt(pos);
            int size = b.getInt(pos + 4);
            int body = pos + 8;
            if (id == 0x20746D66) { // "fmt "
                format = b.getShort(body) & 0xFFFF;
                channels = b.getShort(body + 2) & 0xFFFF;
                rate = b.getInt(body + 4);
                bits = b.getShort(body + 14) & 0xFFFF;
                if (format == 0xFFFE && size >= 26) { // WAVE_FORMAT_EXTENSIBLE: the sub-format's first two bytes
                    format = b.getShort(body + 24) & 0xFFFF;
                }
            } else if (id == 0x61746164) { // "data"
                if (channels < 1 || !((format == 1 && (bits == 8 || bits == 16)) || (format == 3 && bits == 32))) {
                    throw new IllegalArgumentException(wav + ": only 8- and 16-bit PCM and 32-bit float are read (format "
                            + format + ", " + bits + " bits, " + channels + " channels)");
                }
                int bytesPerSample = bits / 8;
                int end = Math.min(bytes.length, body + Math.max(0, size));
                long frames = (end - body) / ((long) bytesPerSample * channels);
                double[] sum = new double[channels];
                double[] sum2 = new double[channels];
                double peak = 0;
                int p = body;
                for (long f = 0; f < frames; f++) {
                    for (int c = 0; c < channels; c++, p += bytesPerSample) {
                        double v = format == 3 ? b.getFloat(p)
                                : bits == 16 ? b.getShort(p) / 32768.0
                                : ((bytes[p] & 0xFF) - 128) / 128.0; // 8-bit WAV samples are unsigned
                        sum[c] += v;
                        sum2[c] += v * v;
                        peak = Math.max(peak, Math.abs(v));
                    }
                }
                double ac = 0;
                for (int c = 0; c < channels; c++) {
                    double mean = frames == 0 ? 0 : sum[c] / frames;
                    ac += frames == 0 ? 0 : Math.max(0, sum2[c] / frames - mean * mean);
                }
                return new Level(frames, rate, Math.sqrt(ac / channels), peak);
            }
            pos = body + size + (size & 1);
        }
        throw new IllegalArgumentException(wav + " has no data chunk");
    }
}
