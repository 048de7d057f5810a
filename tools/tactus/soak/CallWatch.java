package tactus.soak;

import java.util.concurrent.Callable;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * Times API calls: a thread that calls through {@link #call} publishes what it is doing and since when; a monitor
 * thread ({@link #check}, every few milliseconds) reports each call still running after {@link #limitNanos} as a
 * hang, once, with the stack of the stuck thread. A call that never returns is reported once and stays visible in
 * {@link #stuck()}.
 */
final class CallWatch {
    /** One thread's call in flight. */
    static final class Slot {
        final Thread thread;
        volatile String call;
        volatile long startNanos;
        volatile boolean reported;

        Slot(Thread thread) {
            this.thread = thread;
        }
    }

    private final long limitNanos;
    private final SoakReport report;
    private final CopyOnWriteArrayList<Slot> slots = new CopyOnWriteArrayList<>();
    private final ThreadLocal<Slot> mine = ThreadLocal.withInitial(this::newSlot);

    CallWatch(long limitNanos, SoakReport report) {
        this.limitNanos = limitNanos;
        this.report = report;
    }

    private Slot newSlot() {
        Slot s = new Slot(Thread.currentThread());
        slots.add(s);
        return s;
    }

    /** Runs {@code body} as the named call; its exceptions pass through. */
    <T> T call(String name, Callable<T> body) throws Exception {
        Slot s = mine.get();
        s.call = name;
        s.reported = false;
        s.startNanos = System.nanoTime();
        try {
            return body.call();
        } finally {
            s.startNanos = 0;
            s.call = null;
        }
    }

    /** Reports every call in flight for longer than the limit (once per call). */
    void check() {
        long now = System.nanoTime();
        for (Slot s : slots) {
            long start = s.startNanos;
            if (start != 0 && !s.reported && now - start > limitNanos) {
                s.reported = true;
                String call = s.call;
                report.hang(s.thread.getName(), String.format(java.util.Locale.ROOT, "%s took over %.1f s",
                        call, limitNanos * 1e-9), s.thread.getStackTrace());
            }
        }
    }

    /** @return the calls still running after the limit, one line each (empty when none). */
    String stuck() {
        StringBuilder sb = new StringBuilder();
        long now = System.nanoTime();
        for (Slot s : slots) {
            long start = s.startNanos;
            if (start != 0 && now - start > limitNanos) {
                sb.append(String.format(java.util.Locale.ROOT, "  still stuck: %s in %s for %.1f s%n",
                        s.thread.getName(), s.call, (now - start) * 1e-9));
            }
        }
        return sb.toString();
    }
}
