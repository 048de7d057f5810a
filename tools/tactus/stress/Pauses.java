package tactus.stress;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The safepoints of a JVM, read from its log ({@code -Xlog:safepoint:file=F:timenanos}): each line is written
 * when a safepoint ends, stamped with {@code System.nanoTime()}, and gives the operation and its total time.
 */
final class Pauses {
    private static final Pattern LINE = Pattern.compile(
            "^\\[(\\d+)ns\\] Safepoint \"([^\"]+)\".*Reaching safepoint: (\\d+) ns.*Total: (\\d+) ns");

    private final List<long[]> spans = new ArrayList<>();   // {start, end, 1 if a collection, end of reaching}

    private Pauses() {
    }

    /** The safepoints in the log at {@code path}; none if the path is null or the file cannot be read. */
    static Pauses read(String path) {
        Pauses p = new Pauses();
        if (path == null) {
            return p;
        }
        try {
            for (String line : Files.readAllLines(Paths.get(path), StandardCharsets.UTF_8)) {
                Matcher m = LINE.matcher(line);
                if (m.find()) {
                    long end = Long.parseLong(m.group(1));
                    long reaching = Long.parseLong(m.group(3));
                    long total = Long.parseLong(m.group(4));
                    boolean gc = m.group(2).contains("G1") || m.group(2).contains("GC")
                            || m.group(2).contains("Collect") || m.group(2).contains("Z");
                    p.spans.add(new long[] {end - total, end, gc ? 1 : 0, end - total + reaching});
                }
            }
        } catch (IOException e) {
            System.err.println("StallChild: cannot read the safepoint log " + path + ": " + e.getMessage());
        }
        return p;
    }

    /** Milliseconds of [from, to] (System.nanoTime()) inside safepoints, or inside collections only. */
    double overlapMs(long from, long to, boolean gcOnly) {
        double ms = 0;
        for (long[] s : spans) {
            if (gcOnly && s[2] == 0) {
                continue;
            }
            long lo = Math.max(from, s[0]);
            long hi = Math.min(to, s[1]);
            if (hi > lo) {
                ms += (hi - lo) / 1e6;
            }
        }
        return ms;
    }

    /**
     * Milliseconds of [from, to] spent waiting for threads to reach a safepoint (the part of a safepoint before
     * every Java thread has stopped: a thread that the machine's load keeps off the processor delays it).
     */
    double reachingMs(long from, long to) {
        double ms = 0;
        for (long[] s : spans) {
            long lo = Math.max(from, s[0]);
            long hi = Math.min(to, s[3]);
            if (hi > lo) {
                ms += (hi - lo) / 1e6;
            }
        }
        return ms;
    }

    /** The number of collections. */
    int gcCount() {
        int n = 0;
        for (long[] s : spans) {
            n += (int) s[2];
        }
        return n;
    }

    /** The longest collection's safepoint, in milliseconds. */
    double gcMaxMs() {
        double max = 0;
        for (long[] s : spans) {
            if (s[2] == 1) {
                max = Math.max(max, (s[1] - s[0]) / 1e6);
            }
        }
        return max;
    }
}
