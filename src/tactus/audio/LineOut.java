package tactus.audio;

import ddf.minim.AudioOutput;
import ddf.minim.Minim;
import java.io.PrintStream;

/**
 * Opens Minim's line out, and never returns null. With Tactus on the class path, {@code Minim.getLineOut()} itself
 * works on a machine with no sound card: it plays into the {@link VirtualMixerProvider virtual output}. If it still
 * returns null (Tactus's mixer is not registered, or the format is not one it plays), this class says so clearly
 * and returns an
 * {@code AudioOutput} backed by a {@link SilentAudioOut}, which keeps computing the patched UGens in real
 * time (so models still step and haptics still get forces) and discards the sound. To hear the result
 * anyway, render it with {@link OfflineRenderer}.
 */
public final class LineOut {
    private LineOut() {
    }

    /** Like {@link #open(Minim, int, int, float)} with stereo, 1024-frame buffers and 44.1 kHz. */
    public static AudioOutput open(Minim minim) {
        return open(minim, Minim.STEREO, 1024, 44100f);
    }

    /**
     * Opens Minim's line out, or a silent real-time output where the machine has no sound device.
     *
     * @param type {@code Minim.MONO} or {@code Minim.STEREO}
     * @param bufferSize frames per buffer
     * @param sampleRate frames per second
     * @return Minim's line out, or a silent real-time output if there is none
     */
    public static AudioOutput open(Minim minim, int type, int bufferSize, float sampleRate) {
        return open(minim, type, bufferSize, sampleRate, System.err);
    }

    /** As {@link #open(Minim, int, int, float)}, printing the fallback message on {@code messages}. */
    public static AudioOutput open(Minim minim, int type, int bufferSize, float sampleRate, PrintStream messages) {
        if (minim == null) {
            throw new IllegalArgumentException("LineOut.open: minim must not be null");
        }
        if (type != Minim.MONO && type != Minim.STEREO) {
            throw new IllegalArgumentException("LineOut.open: type must be Minim.MONO or Minim.STEREO, got " + type);
        }
        AudioOutput out = minim.getLineOut(type, bufferSize, sampleRate, 16);
        if (out != null) {
            return out;
        }
        return silent(type, bufferSize, sampleRate, messages);
    }

    /**
     * {@return {@code out} if it is not null, otherwise a silent real-time output with the given format (for
     *     sketches that call {@code minim.getLineOut()} themselves)}
     */
    public static AudioOutput orSilent(AudioOutput out, int type, int bufferSize, float sampleRate) {
        return out != null ? out : silent(type, bufferSize, sampleRate, System.err);
    }

    static AudioOutput silent(int type, int bufferSize, float sampleRate, PrintStream messages) {
        if (messages != null) {
            messages.println("Tactus audio: no sound output (Minim.getLineOut() returned null: no sound card, or "
                    + (type == Minim.STEREO ? "stereo" : "mono") + " " + sampleRate + " Hz 16-bit is not supported). "
                    + "Using a silent output that still runs the audio graph in real time; "
                    + "render to a WAV file with tactus.audio.OfflineRenderer to hear it.");
        }
        return new AudioOutput(new SilentAudioOut(type == Minim.STEREO ? 2 : 1, bufferSize, sampleRate));
    }
}
