package tactus.haptics.safety;

import java.io.File;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.locks.LockSupport;

/**
 * A program (not a test) that measures how long a JVM's heartbeat stays unchanged while the JVM runs normally,
 * to choose the motor guard's heartbeat threshold: a child JVM beats as a sketch's board does (a 1 kHz torque
 * writer and a 5 ms watchdog thread), optionally with a thread making garbage (MB/s), and this JVM polls the
 * shared memory every millisecond (as the guard does) and prints the distribution of the gaps it sees.
 *
 * <pre>java -cp build/classes/java/main:build/classes/java/test tactus.haptics.HeartbeatGapProbe seconds [garbageMBps]</pre>
 */
public final class HeartbeatGapProbe {
    private HeartbeatGapProbe() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length > 0 && args[0].equals("child")) {
            child(args[1], Integer.parseInt(args[2]));
            return;
        }
        int seconds = Integer.parseInt(args[0]);
        int garbage = args.length > 1 ? Integer.parseInt(args[1]) : 0;
        GuardHeartbeat hb = GuardHeartbeat.create();
        String java = System.getProperty("java.home") + File.separator + "bin" + File.separator + "java";
        List<String> cmd = new ArrayList<>(List.of(java, "-Xlog:safepoint=info:file=/tmp/hbprobe-safepoint.log",
                "-cp", System.getProperty("java.class.path"), HeartbeatGapProbe.class.getName(), "child", hb.path(),
                Integer.toString(garbage)));
        Process child = new ProcessBuilder(cmd).inheritIO().start();
        Thread.sleep(1500);   // let it start and warm up
        long[] gaps = new long[seconds * 2000];
        int n = 0;
        long last = hb.heartbeat();
        long changedAt = System.nanoTime();
        long end = System.nanoTime() + seconds * 1_000_000_000L;
        long worst = 0;
        long trueWorst = 0;
        while (System.nanoTime() < end && n < gaps.length) {
            LockSupport.parkNanos(1_000_000);
            long now = System.nanoTime();
            long b = hb.heartbeat();
            // what the guard judges: how long the value has been unchanged at a look that finds it unchanged
            if (b != last) {
                gaps[n++] = now - changedAt;
                last = b;
                changedAt = now;
            } else {
                worst = Math.max(worst, now - changedAt);
            }
            // the beat holds the child's nanoTime (CLOCK_MONOTONIC on Linux, the same in both JVMs)
            trueWorst = Math.max(trueWorst, now - b);
        }
        child.destroy();
        hb.unlink();
        long[] g = Arrays.copyOf(gaps, n);
        Arrays.sort(g);
        System.out.printf("over %d s (garbage %d MB/s): longest unchanged at a 1 ms poll %.2f ms; longest time since the child's last beat %.2f ms; "
                + "intervals between seen changes: n=%d p50 %.2f p99 %.2f p99.9 %.2f max %.2f ms%n",
                seconds, garbage, worst / 1e6, trueWorst / 1e6, n, g[n / 2] / 1e6, g[(int) (n * 0.99)] / 1e6, g[(int) (n * 0.999)] / 1e6, g[n - 1] / 1e6);
        int[] over = {5, 10, 20, 30, 40, 50};
        StringBuilder s = new StringBuilder("  gaps over");
        for (int ms : over) {
            long c = Arrays.stream(g).filter(x -> x > ms * 1_000_000L).count();
            s.append(String.format(" %d ms: %d;", ms, c));
        }
        System.out.println(s);
    }

    private static void child(String path, int garbageMBps) throws Exception {
        GuardHeartbeat hb = GuardHeartbeat.open(path);
        hb.arm(true);
        Thread writer = new Thread(() -> {
            while (true) {
                LockSupport.parkNanos(1_000_000);
                hb.beat(System.nanoTime());
            }
        }, "writer");
        Thread watchdog = new Thread(() -> {
            while (true) {
                LockSupport.parkNanos(5_000_000);
                hb.beat(System.nanoTime());
            }
        }, "watchdog");
        writer.setDaemon(true);
        watchdog.setDaemon(true);
        writer.start();
        watchdog.start();
        if (garbageMBps > 0) {
            Object[] keep = new Object[1024];
            long perMs = garbageMBps * 1000L;   // bytes per ms
            int i = 0;
            while (true) {
                long t0 = System.nanoTime();
                for (long made = 0; made < perMs; made += 1024) {
                    keep[i++ & 1023] = new byte[1000];
                }
                long left = 1_000_000 - (System.nanoTime() - t0);
                if (left > 0) {
                    LockSupport.parkNanos(left);
                }
            }
        }
        Thread.sleep(Long.MAX_VALUE);
    }
}
