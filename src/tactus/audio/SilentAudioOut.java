package tactus.audio;

import ddf.minim.AudioEffect;
import ddf.minim.AudioListener;
import ddf.minim.AudioSignal;
import ddf.minim.spi.AudioOut;
import ddf.minim.spi.AudioStream;
import java.util.concurrent.locks.LockSupport;
import javax.sound.sampled.AudioFormat;
import javax.sound.sampled.Control;

/**
 * A Minim {@code AudioOut} with no device behind it: a daemon thread computes one buffer at a time at the
 * pace of the sample rate (so a {@link PhyUGen} patched into it still steps its model in real time, and
 * the output's {@code left/right/mix} buffers and recorders still get the samples) and discards the sound.
 * Wrap it as {@code new AudioOutput(new SilentAudioOut(...))}; {@link LineOut} does so when there is no
 * sound card. When the system property {@value HeadlessRecording#PROPERTY} names a WAV file, what it computes is
 * recorded there as 16-bit PCM (see {@link HeadlessRecording}).
 */
@SuppressWarnings("deprecation") // Minim's AudioOut SPI is built on its deprecated AudioSignal and AudioEffect
public final class SilentAudioOut implements AudioOut {
    private final AudioFormat format;
    private final int bufferSize;
    private volatile AudioSignal signal;
    private volatile AudioEffect effect;
    private volatile AudioListener listener;
    private volatile boolean running;
    private volatile long buffersRendered;
    private Thread thread;

    /**
     * Creates a silent output that consumes samples in real time, for machines with no sound device.
     *
     * @param channels 1 (mono) or 2 (stereo)
     * @param bufferSize frames per buffer (&gt; 0)
     * @param sampleRate frames per second (&gt; 0)
     */
    public SilentAudioOut(int channels, int bufferSize, float sampleRate) {
        if (channels < 1 || channels > 2 || bufferSize <= 0 || !(sampleRate > 0)) {
            throw new IllegalArgumentException("SilentAudioOut: need 1 or 2 channels, bufferSize > 0, sampleRate > 0; got "
                    + channels + ", " + bufferSize + ", " + sampleRate);
        }
        this.format = new AudioFormat(sampleRate, 16, channels, true, false);
        this.bufferSize = bufferSize;
    }

    /** The output's thread: {@link AudioScheduling} asks real-time scheduling for it when it plays a PhyUGen. */
    static final class OutputThread extends Thread {
        OutputThread(Runnable body) {
            super(body, "Tactus silent audio out");
        }
    }

    @Override
    public synchronized void open() {
        if (running) {
            return;
        }
        running = true;
        thread = new OutputThread(this::run);
        thread.setDaemon(true);
        thread.setPriority(Thread.MAX_PRIORITY);
        thread.start();
    }

    @Override
    public void close() {
        Thread t;
        synchronized (this) {
            running = false;
            t = thread;
            thread = null;
        }
        if (t != null && t != Thread.currentThread()) {
            try {
                t.join(5000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** {@return the number of buffers computed so far} */
    public long buffersRendered() {
        return buffersRendered;
    }

    private void run() {
        boolean stereo = format.getChannels() == 2;
        float[] left = new float[bufferSize];
        float[] right = new float[bufferSize];
        long period = Math.round(bufferSize * 1e9 / format.getSampleRate());
        long deadline = System.nanoTime();
        HeadlessRecording rec = HeadlessRecording.claim(format);
        byte[] pcm = rec == null ? null : new byte[bufferSize * 4];
        while (running) {
            AudioSignal s = signal;
            java.util.Arrays.fill(left, 0f);
            java.util.Arrays.fill(right, 0f);
            if (s != null) {
                if (stereo) {
                    s.generate(left, right);
                } else {
                    s.generate(left);
                }
            }
            AudioEffect e = effect;
            AudioListener l = listener;
            if (stereo) {
                if (e != null) {
                    e.process(left, right);
                }
                if (l != null) {
                    l.samples(left, right);
                }
            } else {
                if (e != null) {
                    e.process(left);
                }
                if (l != null) {
                    l.samples(left);
                }
            }
            if (rec != null) {
                rec.writeFloats(left, stereo ? right : null, bufferSize, pcm);
            }
            buffersRendered++;
            deadline += period;
            long wait = deadline - System.nanoTime();
            if (wait > 0) {
                LockSupport.parkNanos(wait);
            } else if (wait < -1_000_000_000L) {
                deadline = System.nanoTime(); // fell behind by over a second: do not try to catch up
            }
        }
        if (rec != null) {
            rec.close();
        }
    }

    @Override
    public int bufferSize() {
        return bufferSize;
    }

    @Override
    public void setAudioSignal(AudioSignal signal) {
        this.signal = signal;
    }

    @Override
    public void setAudioStream(AudioStream stream) {
        throw new UnsupportedOperationException("SilentAudioOut plays signals (UGens), not streams");
    }

    @Override
    public void setAudioEffect(AudioEffect effect) {
        this.effect = effect;
    }

    @Override
    public void setAudioListener(AudioListener listener) {
        this.listener = listener;
    }

    @Override
    public Control[] getControls() {
        return new Control[0];
    }

    @Override
    public AudioFormat getFormat() {
        return format;
    }
}
