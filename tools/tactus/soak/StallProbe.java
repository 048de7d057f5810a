package tactus.soak;

import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.locks.LockSupport;
import tactus.scheduling.RealtimeThreads;

/**
 * The soak's {@code --diagnose} option: a thread at a real-time priority above the audio output thread's that looks
 * every 2 ms for an audio output with no block for {@link #STALL_NANOS}, and then records where the output thread is
 * (its state, its top frame and its Tactus frames), and again if the stall lasts {@link #LONG_STALL_NANOS}. At the end it prints how many stalls it
 * saw at each place: the evidence of what holds the audio thread up under load. Not part of a normal run.
 */
final class StallProbe implements Runnable {
    /** An output without a block for this long is looked at, ns (two 512-frame blocks are 23 ms). */
    static final long STALL_NANOS = 30_000_000L;
    /** A stall this long is looked at again, ns. */
    static final long LONG_STALL_NANOS = 200_000_000L;
    private static final int PRIORITY = 60;
    private final AudioWatch watch;
    private final Map<String, Integer> places = new TreeMap<>();
    private volatile boolean running = true;
    private volatile String scheduling = "not started";

    StallProbe(AudioWatch watch) {
        this.watch = watch;
    }

    @Override
    public void run() {
        String why = RealtimeThreads.applyWithCurrentThread(Map.of(), PRIORITY);
        scheduling = why == null ? "SCHED_FIFO " + PRIORITY : "normal priority (" + why + ")";
        long lookedAt = 0;
        long lookedAgainAt = 0;
        while (running) {
            LockSupport.parkNanos(2_000_000L);
            long last = watch.lastBlockNanos();
            Thread t = watch.audioThread();
            long now = System.nanoTime();
            if (t == null || last == 0 || now - last < STALL_NANOS) {
                continue;
            }
            String prefix = "";
            if (last == lookedAt) {
                if (now - last < LONG_STALL_NANOS || last == lookedAgainAt) {
                    continue;
                }
                lookedAgainAt = last;   // a second look at a long stall
                prefix = "(after " + LONG_STALL_NANOS / 1_000_000 + " ms) ";
            }
            lookedAt = last;   // one look per stall
            String place = prefix + place(t);
            synchronized (places) {
                places.merge(place, 1, Integer::sum);
            }
        }
    }

    /** The thread's state, its top frame, and every Tactus frame below it down to the PhyUGen's. */
    private static String place(Thread t) {
        StringBuilder sb = new StringBuilder(t.getState().toString());
        StackTraceElement[] st = t.getStackTrace();
        for (int i = 0; i < st.length; i++) {
            StackTraceElement f = st[i];
            boolean ours = f.getClassName().startsWith("tactus.");
            if (i > 0 && !ours) {
                continue;
            }
            sb.append(i == 0 ? ": " : " < ").append(f.getClassName().replaceAll("^.*\\.", ""))
                    .append('.').append(f.getMethodName());
            if (f.getClassName().startsWith("tactus.audio.")) {
                break;
            }
        }
        return sb.toString();
    }

    void stop() {
        running = false;
    }

    /** @return the stalls seen at each place, most frequent first, one per line. */
    String summary() {
        StringBuilder sb = new StringBuilder("  stall probe (" + scheduling + "), audio output without a block for "
                + STALL_NANOS / 1_000_000 + " ms, where its thread was:\n");
        synchronized (places) {
            if (places.isEmpty()) {
                sb.append("    none\n");
            }
            places.entrySet().stream().sorted((a, b) -> b.getValue() - a.getValue())
                    .forEach(e -> sb.append("    ").append(e.getValue()).append(" x ").append(e.getKey()).append('\n'));
        }
        return sb.toString();
    }
}
