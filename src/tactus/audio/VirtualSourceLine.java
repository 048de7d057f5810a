package tactus.audio;

import java.util.concurrent.locks.LockSupport;
import javax.sound.sampled.AudioFormat;
import javax.sound.sampled.AudioSystem;
import javax.sound.sampled.DataLine;
import javax.sound.sampled.Line;
import javax.sound.sampled.SourceDataLine;

/**
 * The output line of the {@link VirtualMixer}: a device that plays at the format's frame rate into nothing. Its
 * buffer (the size given to {@code open}, default half a second) fills with each {@code write} and empties in real
 * time from the first write on; a write blocks only until there is room, as with a sound card, so a Minim output
 * thread writing into it computes its buffers at the pace of the sample rate. If the writer falls behind, the line
 * runs dry and restarts its clock at the next write (an underrun, silent). Every byte written is also appended to
 * the run's {@link HeadlessRecording} when {@value HeadlessRecording#PROPERTY} is set.
 */
final class VirtualSourceLine extends BareLine implements SourceDataLine {
    private final DataLine.Info info;
    private AudioFormat format;
    private int bufferBytes;
    private int frameSize;
    private volatile boolean open;
    private volatile boolean running;
    /** Frames written since the clock (re)started, and when it started (ns); the device plays from then on. */
    private long written;
    private long clockStart;
    private long playedBefore;
    private HeadlessRecording recording;

    VirtualSourceLine(DataLine.Info info, AudioFormat format) {
        this.info = info;
        this.format = format;
    }

    @Override
    public void open(AudioFormat format, int bufferSize) {
        if (format == null || !AudioFormat.Encoding.PCM_SIGNED.equals(format.getEncoding())
                || (format.getSampleSizeInBits() != 8 && format.getSampleSizeInBits() != 16)
                || format.getChannels() < 1 || format.getChannels() > 2 || !(format.getFrameRate() > 0)) {
            throw new IllegalArgumentException("Tactus virtual output: cannot play " + format
                    + " (signed 8- or 16-bit PCM, 1 or 2 channels, a known rate)");
        }
        synchronized (this) {
            if (open) {
                return;
            }
            this.format = format;
            this.frameSize = format.getFrameSize();
            int half = Math.max(frameSize, Math.round(format.getFrameRate() / 2) * frameSize);
            int asked = bufferSize > 0 ? bufferSize : half;
            this.bufferBytes = Math.max(frameSize, asked - asked % frameSize);
            this.written = 0;
            this.playedBefore = 0;
            this.clockStart = -1;
            this.recording = HeadlessRecording.claim(format);
            open = true;
        }
    }

    @Override
    public void open(AudioFormat format) {
        open(format, AudioSystem.NOT_SPECIFIED);
    }

    @Override
    public void open() {
        open(format);
    }

    /** @return frames played since the clock started, at most the frames written. */
    private synchronized long playedSinceStart(long now) {
        if (clockStart < 0) {
            return 0;
        }
        long played = (long) ((now - clockStart) * 1e-9 * format.getFrameRate());
        return Math.min(played, written);
    }

    /** @return frames waiting in the buffer. */
    private synchronized long queued(long now) {
        return written - playedSinceStart(now);
    }

    @Override
    public int write(byte[] b, int off, int len) {
        if (len % Math.max(1, frameSize) != 0) {
            throw new IllegalArgumentException("Tactus virtual output: write of " + len
                    + " bytes is not a whole number of " + frameSize + "-byte frames");
        }
        int done = 0;
        while (done < len && open) {
            long now = System.nanoTime();
            long free;
            synchronized (this) {
                if (clockStart < 0 || playedSinceStart(now) >= written) {
                    // first write, or the line ran dry: the device starts playing from now
                    playedBefore += written;
                    written = 0;
                    clockStart = now;
                }
                free = bufferBytes - queued(now) * frameSize;
            }
            if (free < frameSize) {
                long frames = Math.max(1, (len - done) / frameSize - (free / frameSize));
                long wait = (long) (Math.min(frames, bufferBytes / frameSize / 4 + 1) * 1e9 / format.getFrameRate());
                LockSupport.parkNanos(Math.max(100_000L, wait));
                continue;
            }
            int chunk = (int) Math.min(len - done, free - free % frameSize);
            HeadlessRecording r = recording;
            if (r != null) {
                r.write(b, off + done, chunk, format.getSampleSizeInBits() == 8);
            }
            synchronized (this) {
                written += chunk / frameSize;
            }
            done += chunk;
        }
        return done;
    }

    @Override
    public void drain() {
        while (open) {
            long q = queued(System.nanoTime());
            if (q <= 0) {
                return;
            }
            LockSupport.parkNanos(Math.max(100_000L, (long) (q * 1e9 / format.getFrameRate())));
        }
    }

    @Override
    public synchronized void flush() {
        long now = System.nanoTime();
        playedBefore += playedSinceStart(now);
        written = 0;
        clockStart = -1;
    }

    @Override
    public void start() {
        running = true;
    }

    @Override
    public void stop() {
        running = false;
    }

    @Override
    public boolean isRunning() {
        return running;
    }

    @Override
    public boolean isActive() {
        return running && queued(System.nanoTime()) > 0;
    }

    @Override
    public AudioFormat getFormat() {
        return format;
    }

    @Override
    public int getBufferSize() {
        return bufferBytes;
    }

    @Override
    public int available() {
        if (!open) {
            return 0;
        }
        long free = bufferBytes - queued(System.nanoTime()) * frameSize;
        return (int) Math.max(0, free);
    }

    @Override
    public int getFramePosition() {
        return (int) getLongFramePosition();
    }

    @Override
    public synchronized long getLongFramePosition() {
        return playedBefore + playedSinceStart(System.nanoTime());
    }

    @Override
    public long getMicrosecondPosition() {
        return (long) (getLongFramePosition() * 1e6 / format.getFrameRate());
    }

    @Override
    public float getLevel() {
        return AudioSystem.NOT_SPECIFIED;
    }

    @Override
    public Line.Info getLineInfo() {
        return info;
    }

    @Override
    public void close() {
        HeadlessRecording r;
        synchronized (this) {
            open = false;
            running = false;
            r = recording;
            recording = null;
        }
        if (r != null) {
            r.close();
        }
    }

    @Override
    public boolean isOpen() {
        return open;
    }
}
