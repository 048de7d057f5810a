package tactus.haptics;

import java.util.Map;
import java.util.regex.Pattern;
import tactus.scheduling.RealtimeThreads;

/**
 * The haptic loop's view of {@link RealtimeThreads} (where the code now lives, shared with the audio output thread):
 * used once, before the first tick, by the haptic loop when {@link HapticLoop#setRealtimePriority(int)} asks for it,
 * for the loop thread itself, its safety threads, and the JVM's threads that a Java thread can end up waiting for
 * (the VM thread and the collector's pause workers one step below the loop, the JIT compilers at the lowest
 * real-time priority); see docs/haptics.md, "Why the loop was late".
 */
final class RealtimeScheduling {
    /** See {@link RealtimeThreads#SAFEPOINT_THREADS}. */
    static final Pattern SAFEPOINT_THREADS = RealtimeThreads.SAFEPOINT_THREADS;
    /** See {@link RealtimeThreads#COMPILER_THREADS}. */
    static final Pattern COMPILER_THREADS = RealtimeThreads.COMPILER_THREADS;

    private RealtimeScheduling() {
    }

    /** See {@link RealtimeThreads#applyWithCurrentThread(Map, int)}. */
    static String applyWithCurrentThread(Map<Pattern, Integer> others, int priority) {
        return RealtimeThreads.applyWithCurrentThread(others, priority);
    }
}
