package tactus.audio;

import ddf.minim.UGen;
import ddf.minim.ugens.Summer;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;

/**
 * Renders a Minim UGen graph (a {@link PhyUGen} or anything patched into one UGen) with no sound card, as
 * fast as the CPU allows: the graph is patched into a private {@code Summer} that is ticked frame by frame,
 * then unpatched again. Long renders print a progress line about once a second on the given stream (from
 * the rendering thread, between blocks of frames; nothing is printed per sample).
 */
public final class OfflineRenderer {
    /** Renders longer than this much wall time print progress lines. */
    private static final long PROGRESS_EVERY_NANOS = 1_000_000_000L;
    private static final int BLOCK = 4096;

    private OfflineRenderer() {
    }

    /** What a render did. */
    public static final class Result {
        /** Frames rendered. */
        public final long frames;
        /** Largest absolute sample value. */
        public final double peak;
        /** Wall time spent, in seconds. */
        public final double wallSeconds;
        /** Audio seconds rendered per wall second. */
        public final double speed;

        Result(long frames, double peak, double wallSeconds, double sampleRate) {
            this.frames = frames;
            this.peak = peak;
            this.wallSeconds = wallSeconds;
            this.speed = wallSeconds > 0 ? frames / sampleRate / wallSeconds : Double.POSITIVE_INFINITY;
        }

        @Override
        public String toString() {
            return String.format(java.util.Locale.ROOT, "%d frames, peak %.4f, %.3f s wall, %.1fx real time", frames, peak,
                    wallSeconds, speed);
        }
    }

    /** Receives rendered frames. */
    private interface FrameSink {
        void accept(float[] frame, long index) throws IOException;
    }

    /**
     * Renders to a WAV file.
     *
     * @param graph the UGen whose output is rendered (it must not be patched into a running AudioOutput)
     * @param progress where progress lines go on long renders, or null for none
     */
    public static Result renderToWav(UGen graph, float sampleRate, int channels, double seconds, File wav,
            WavWriter.Encoding encoding, PrintStream progress) throws IOException {
        return renderToWav(graph, sampleRate, channels, seconds, wav, encoding, progress, PROGRESS_EVERY_NANOS);
    }

    static Result renderToWav(UGen graph, float sampleRate, int channels, double seconds, File wav,
            WavWriter.Encoding encoding, PrintStream progress, long progressEveryNanos) throws IOException {
        long frames = frameCount(sampleRate, seconds);
        try (WavWriter w = new WavWriter(wav, Math.round(sampleRate), channels, frames, encoding)) {
            return render(graph, sampleRate, channels, frames, (frame, i) -> w.writeFrame(frame),
                    progress, wav.getName(), progressEveryNanos);
        }
    }

    /**
     * Renders into memory.
     *
     * @return out[channel][frame]
     */
    public static float[][] renderToArray(UGen graph, float sampleRate, int channels, double seconds) {
        long frames = frameCount(sampleRate, seconds);
        if (frames > Integer.MAX_VALUE) {
            throw new IllegalArgumentException("renderToArray: " + frames + " frames do not fit in an array");
        }
        float[][] out = new float[channels][(int) frames];
        try {
            render(graph, sampleRate, channels, frames, (frame, i) -> {
                for (int c = 0; c < channels; c++) {
                    out[c][(int) i] = frame[c];
                }
            }, null, "array", PROGRESS_EVERY_NANOS);
        } catch (IOException e) {
            throw new IllegalStateException(e); // the array sink never throws
        }
        return out;
    }

    private static long frameCount(float sampleRate, double seconds) {
        if (!(sampleRate > 0) || !(seconds >= 0) || Double.isInfinite(seconds)) {
            throw new IllegalArgumentException("OfflineRenderer: need sampleRate > 0 and seconds >= 0, got " + sampleRate
                    + " Hz and " + seconds + " s");
        }
        return Math.round(seconds * sampleRate);
    }

    private static Result render(UGen graph, float sampleRate, int channels, long frames, FrameSink sink,
            PrintStream progress, String label, long progressEveryNanos) throws IOException {
        if (graph == null) {
            throw new IllegalArgumentException("OfflineRenderer: the graph must not be null");
        }
        if (channels < 1 || channels > 8) {
            throw new IllegalArgumentException("OfflineRenderer: channels must be 1..8, got " + channels);
        }
        Summer root = new Summer();
        graph.patch(root);
        try {
            graph.setSampleRate(sampleRate);
            graph.setChannelCount(channels);
            root.setSampleRate(sampleRate);
            root.setChannelCount(channels);
            float[] frame = new float[channels];
            double peak = 0;
            long start = System.nanoTime();
            long nextReport = start + progressEveryNanos;
            for (long i = 0; i < frames; i++) {
                java.util.Arrays.fill(frame, 0f);
                root.tick(frame);
                for (int c = 0; c < channels; c++) {
                    peak = Math.max(peak, Math.abs(frame[c]));
                }
                sink.accept(frame, i);
                if (progress != null && (i % BLOCK) == BLOCK - 1) {
                    long now = System.nanoTime();
                    if (now >= nextReport) {
                        double wall = (now - start) * 1e-9;
                        double done = (i + 1) / (double) sampleRate;
                        progress.printf(java.util.Locale.ROOT, "rendering %s: %3.0f%% (%.1f of %.1f s), %.1fx real time%n",
                                label, 100.0 * (i + 1) / frames, done, frames / (double) sampleRate, done / wall);
                        nextReport = now + progressEveryNanos;
                    }
                }
            }
            double wall = (System.nanoTime() - start) * 1e-9;
            Result r = new Result(frames, peak, wall, sampleRate);
            if (progress != null && wall * 1e9 >= progressEveryNanos) {
                progress.println("rendered " + label + ": " + r);
            }
            return r;
        } finally {
            graph.unpatch(root);
        }
    }
}
