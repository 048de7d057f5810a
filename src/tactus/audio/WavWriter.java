package tactus.audio;

import java.io.BufferedOutputStream;
import java.io.Closeable;
import java.io.File;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.OutputStream;

/**
 * Writes interleaved frames to a RIFF/WAVE file, as 16-bit PCM (clipped to [-1, 1]) or 32-bit IEEE float,
 * with the frame count known in advance so the header is written once.
 */
public final class WavWriter implements Closeable {
    /** Sample encodings. */
    public enum Encoding {
        /** Signed 16-bit little-endian PCM; samples are clipped to [-1, 1]. */
        PCM_16,
        /** 32-bit IEEE float, unclipped. */
        FLOAT_32
    }

    private final OutputStream out;
    private final Encoding encoding;
    private final int channels;
    private final long frames;
    private long written;
    private final byte[] buffer = new byte[4];

    /**
     * Opens the file and writes its header.
     *
     * @param frames the number of frames that will be written
     */
    public WavWriter(File file, int sampleRate, int channels, long frames, Encoding encoding) throws IOException {
        if (channels < 1 || sampleRate <= 0 || frames < 0 || encoding == null) {
            throw new IllegalArgumentException("WavWriter(" + file + "): bad format: " + sampleRate + " Hz, " + channels
                    + " channels, " + frames + " frames, " + encoding);
        }
        this.encoding = encoding;
        this.channels = channels;
        this.frames = frames;
        int bytesPerSample = encoding == Encoding.PCM_16 ? 2 : 4;
        long dataBytes = frames * channels * bytesPerSample;
        if (dataBytes + 36 > 0xFFFFFFFFL) {
            throw new IllegalArgumentException("WavWriter(" + file + "): " + frames + " frames exceed the 4 GB WAV limit");
        }
        this.out = new BufferedOutputStream(new FileOutputStream(file), 1 << 16);
        ascii("RIFF");
        int32(36 + dataBytes);
        ascii("WAVE");
        ascii("fmt ");
        int32(16);
        int16(encoding == Encoding.PCM_16 ? 1 : 3);
        int16(channels);
        int32(sampleRate);
        int32((long) sampleRate * channels * bytesPerSample);
        int16(channels * bytesPerSample);
        int16(bytesPerSample * 8);
        ascii("data");
        int32(dataBytes);
    }

    /** Writes one interleaved frame (its length must be the channel count). */
    public void writeFrame(float[] frame) throws IOException {
        if (written == frames) {
            throw new IllegalStateException("WavWriter: all " + frames + " frames have been written");
        }
        for (int c = 0; c < channels; c++) {
            float v = frame[c];
            if (encoding == Encoding.PCM_16) {
                double clipped = v != v ? 0 : Math.max(-1, Math.min(1, v));
                int16((int) Math.round(clipped * 32767));
            } else {
                int32(Float.floatToRawIntBits(v) & 0xFFFFFFFFL);
            }
        }
        written++;
    }

    /** Closes the file; throws if fewer frames than announced were written. */
    @Override
    public void close() throws IOException {
        out.close();
        if (written != frames) {
            throw new IOException("WavWriter: " + written + " frames written, " + frames + " announced");
        }
    }

    private void ascii(String s) throws IOException {
        for (int i = 0; i < 4; i++) {
            out.write(s.charAt(i));
        }
    }

    private void int16(int v) throws IOException {
        buffer[0] = (byte) v;
        buffer[1] = (byte) (v >> 8);
        out.write(buffer, 0, 2);
    }

    private void int32(long v) throws IOException {
        buffer[0] = (byte) v;
        buffer[1] = (byte) (v >> 8);
        buffer[2] = (byte) (v >> 16);
        buffer[3] = (byte) (v >> 24);
        out.write(buffer, 0, 4);
    }
}
