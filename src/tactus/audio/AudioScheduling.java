package tactus.audio;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.WeakHashMap;
import java.util.regex.Pattern;
import tactus.scheduling.RealtimeThreads;

/**
 * Real-time scheduling for the audio output thread that plays a {@link PhyUGen}: Minim's output thread (behind
 * {@code Minim.getLineOut()}, whatever line it writes to: a sound card or Tactus's virtual output) or the thread of a
 * {@link SilentAudioOut}. When a PhyUGen first computes a sample on such a thread, that thread is moved to Linux's
 * SCHED_FIFO at {@link #realtimePriority()} (default {@value #DEFAULT_PRIORITY}), and the JVM's VM and collector
 * pause threads are raised to at least one above it and its JIT compilers to at least 1 (as the haptic loop does,
 * docs/haptics.md "Why the loop was late"), so that the sketch's own threads and other programs on a busy machine no
 * longer delay the output into a gap (docs/audio.md, "Audio under load"). The request is made by the
 * {@link AudioHelper} thread: the audio thread only hands its id over, once, and never waits. A thread that
 * calls a PhyUGen's {@code uGenerate} itself (an {@link OfflineRenderer}, a sketch) is left alone.
 *
 * <p>Order with the haptic loop: the haptic loop (SCHED_FIFO 50 in a {@code HapticSession}) goes first, then the
 * JVM's VM and collector threads (49), then the audio thread (45): a haptic tick takes microseconds every
 * millisecond and a late one pushes the hand with a stale force, while a 512-frame audio block takes milliseconds
 * every 11.6 ms and the line's buffer gives it slack; the VM and collector threads stand above both because both
 * wait for every safepoint.
 *
 * <p>Where it is refused (not Linux, no right to raise priorities: root, {@code CAP_SYS_NICE} or an
 * {@code rtprio} limit), the output thread keeps its normal priority, {@link #status()} says why, and one line on
 * standard error says so. {@link #setRealtimePriority(int)} (or {@code -D}{@value #PROPERTY}{@code =0}) turns the
 * request off.
 */
public final class AudioScheduling {
    /** The audio output thread's real-time priority unless set otherwise: below a haptic loop's 50 and the JVM's 49. */
    public static final int DEFAULT_PRIORITY = 45;
    /** System property that sets the priority at start-up: 0 turns the request off, 1..99 is the priority. */
    public static final String PROPERTY = "tactus.audio.realtimePriority";
    private static final String MINIM_OUTPUT = "ddf.minim.javasound.JSAudioOutput";

    private static volatile int priority = initialPriority();
    private static volatile String status = "no audio output thread has played a PhyUGen yet";
    private static volatile Thread scheduled;
    /** The output threads already asked for (touched by the helper thread only). */
    private static final Map<Thread, Boolean> ASKED = new WeakHashMap<>();

    private AudioScheduling() {
    }

    private static int initialPriority() {
        String p = System.getProperty(PROPERTY);
        if (p == null) {
            return DEFAULT_PRIORITY;
        }
        try {
            int v = Integer.parseInt(p.trim());
            if (v >= 0 && v <= 99) {
                return v;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        System.err.println("Tactus audio: -D" + PROPERTY + "=" + p + " is not 0 (off) or a priority 1..99; using "
                + DEFAULT_PRIORITY);
        return DEFAULT_PRIORITY;
    }

    /**
     * Sets the real-time priority asked for output threads that start playing a PhyUGen from now on (a thread
     * already moved keeps its policy).
     *
     * @param p 0 to ask for nothing, or 1..99 (Linux SCHED_FIFO priority)
     */
    public static void setRealtimePriority(int p) {
        if (p < 0 || p > 99) {
            throw new IllegalArgumentException("AudioScheduling.setRealtimePriority: priority must be 0 (off) or "
                    + "1..99, got " + p);
        }
        priority = p;
    }

    /** {@return the priority asked for output threads: 0 (off) or 1..99} */
    public static int realtimePriority() {
        return priority;
    }

    /**
     * {@return how the latest output thread that played a PhyUGen is scheduled: "real-time (SCHED_FIFO 45 for thread
     *     "...", VM and GC threads at 46 or above, JIT compilers at 1 or above)", "normal priority (real-time
     *     refused: why)", "normal priority (real-time not requested)", or that none has played yet}
     */
    public static String status() {
        return status;
    }

    /** @return the output thread last moved to real-time scheduling, or null (for tests). */
    static Thread scheduledThread() {
        return scheduled;
    }

    /** @return true for a thread whose pace is a device's: Minim's output thread or a {@link SilentAudioOut}'s. */
    static boolean isOutputThread(Thread t) {
        return t instanceof SilentAudioOut.OutputThread || t.getClass().getName().equals(MINIM_OUTPUT);
    }

    /**
     * Called by a PhyUGen on the thread that computes its samples, when that thread is not the one it saw last:
     * an output thread hands its id to the helper (once; a few microseconds) and returns at once. Never blocks.
     */
    static void computingOn(Thread t) {
        if (!isOutputThread(t) || priority == 0) {
            return;
        }
        String threadId = RealtimeThreads.currentThreadId();
        AudioHelper.post(() -> ask(t, threadId));
    }

    /** On the helper thread: asks once per output thread. */
    private static void ask(Thread t, String threadId) {
        if (ASKED.put(t, Boolean.TRUE) != null || !t.isAlive()) {
            return;
        }
        try {
            apply(t, threadId);
        } catch (RuntimeException e) {
            status = "normal priority (real-time request failed: " + e + ")";
        }
    }

    private static void apply(Thread thread, String threadId) {
        int p = priority;
        if (p == 0) {
            status = "normal priority (real-time not requested)";
            return;
        }
        String why;
        if (threadId == null) {
            why = "real-time scheduling is only requested on Linux";
        } else {
            Map<Pattern, Integer> others = new LinkedHashMap<>();
            others.put(RealtimeThreads.SAFEPOINT_THREADS, Math.min(99, p + 1));
            others.put(RealtimeThreads.COMPILER_THREADS, 1);
            why = RealtimeThreads.applyToThread(threadId, others, p);
        }
        if (why == null) {
            scheduled = thread;
            status = "real-time (SCHED_FIFO " + p + " for thread \"" + thread.getName() + "\", VM and GC threads at "
                    + Math.min(99, p + 1) + " or above, JIT compilers at 1 or above)";
        } else {
            status = "normal priority (real-time refused: " + why + ")";
            System.err.println("Tactus audio: the output thread \"" + thread.getName() + "\" runs at normal "
                    + "priority (real-time refused: " + why + "). On a busy machine the sound may have gaps; see "
                    + "docs/audio.md, \"Audio under load\".");
        }
    }
}
