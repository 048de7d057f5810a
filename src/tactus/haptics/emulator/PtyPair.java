package tactus.haptics.emulator;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Two connected pseudo-terminals made by {@code socat -d -d pty,raw,echo=0 pty,raw,echo=0} (Linux, macOS):
 * open one end as the host's serial port and serve the emulator on the other, so that the real serial code
 * path runs without hardware.
 */
public final class PtyPair implements AutoCloseable {
    private static final Pattern PTY = Pattern.compile("PTY is (\\S+)");

    private final Process socat;
    private final String hostEnd;
    private final String boardEnd;

    private PtyPair(Process socat, String hostEnd, String boardEnd) {
        this.socat = socat;
        this.hostEnd = hostEnd;
        this.boardEnd = boardEnd;
    }

    /** True if a socat executable can be started. */
    public static boolean socatAvailable() {
        try {
            Process p = new ProcessBuilder("socat", "-V").redirectErrorStream(true).start();
            p.getInputStream().readAllBytes();
            return p.waitFor(5, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    /** Starts socat and waits (up to 5 s) until it has printed both pty names. */
    public static PtyPair open() throws IOException {
        Process p = new ProcessBuilder("socat", "-d", "-d", "pty,raw,echo=0", "pty,raw,echo=0").start();
        BufferedReader err = new BufferedReader(new InputStreamReader(p.getErrorStream(), StandardCharsets.UTF_8));
        String[] names = new String[2];
        int found = 0;
        long deadline = System.nanoTime() + 5_000_000_000L;
        StringBuilder log = new StringBuilder();
        while (found < 2 && System.nanoTime() < deadline) {
            String line = err.readLine();
            if (line == null) {
                break;
            }
            log.append(line).append('\n');
            Matcher m = PTY.matcher(line);
            if (m.find()) {
                names[found++] = m.group(1);
            }
        }
        if (found < 2) {
            p.destroyForcibly();
            throw new IOException("socat did not report two ptys; its output was:\n" + log);
        }
        Thread drain = new Thread(() -> {
            try {
                while (err.readLine() != null) {
                    // keep socat's stderr from filling up
                }
            } catch (IOException ignored) {
                // socat ended
            }
        }, "tactus-socat-stderr");
        drain.setDaemon(true);
        drain.start();
        return new PtyPair(p, names[0], names[1]);
    }

    /** The path of the host's end (open it as the serial port). */
    public String hostEnd() {
        return hostEnd;
    }

    /** The path of the board's end (serve the emulator on it). */
    public String boardEnd() {
        return boardEnd;
    }

    /** True while socat runs. */
    public boolean isAlive() {
        return socat.isAlive();
    }

    /** Stops socat: both ptys go away, like a USB cable pulled out. */
    @Override
    public void close() {
        socat.destroy();
        try {
            if (!socat.waitFor(2, TimeUnit.SECONDS)) {
                socat.destroyForcibly();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            socat.destroyForcibly();
        }
    }
}
