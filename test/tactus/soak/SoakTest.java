package tactus.soak;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The soak tool ({@link Soak}) for {@value #SECONDS} s in a child JVM: a PhyUGen on Minim's output thread, a haptic
 * loop on the board emulator, a 60 fps reader and a thread of random valid and invalid calls on one model. Nothing
 * may escape a thread, no call may take over a second, no NaN may reach the audio output or the motors. The child
 * JVM keeps a hang from leaking into the suite; it is killed if it outlives its bound.
 *
 * <p>Why 60 s: the issue asks for it, and it is what it takes for the rarer calls (weight 1 in about 170, one call
 * every 2 ms: a few hundred of each) to meet every state of the audio and haptic threads; the suite's budget (well
 * under 15 minutes on a 2-core machine, about 6 today) has room for one such minute.
 */
class SoakTest {
    static final int SECONDS = 60;
    static final long SEED = 1;
    /** The child's bound: the soak, its start and its shutdown (at most 10 s), with room for a loaded machine. */
    static final long CHILD_LIMIT_SECONDS = SECONDS + 60;

    @TempDir
    Path dir;

    @Test
    @Timeout(SECONDS + 90)
    void sixtySecondsOfAudioHapticsDrawingAndRandomCallsWithNoEscapeHangOrNaN() throws Exception {
        Path log = dir.resolve("soak.log");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = List.of(java, "-Xmx512m", "-XX:-OmitStackTraceInFastThrow", "-Djava.awt.headless=true",
                "-Dfile.encoding=UTF-8", "-cp", System.getProperty("java.class.path"), Soak.class.getName(),
                Integer.toString(SECONDS), Long.toString(SEED));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        boolean done = false;
        try {
            done = p.waitFor(CHILD_LIMIT_SECONDS, TimeUnit.SECONDS);
        } finally {
            if (!done) {
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly();
                p.waitFor(5, TimeUnit.SECONDS);
            }
        }
        String output = read(log);
        if (!done) {
            fail("the soak did not end within " + CHILD_LIMIT_SECONDS + " s and was killed:\n" + tail(output));
        }
        Map<String, Double> r = result(output);
        String failures = failures(output);
        assertEquals(0.0, r.get("escapes"), "exceptions escaped a thread:\n" + failures);
        assertEquals(0.0, r.get("hangs"), "calls or threads hung:\n" + failures);
        assertEquals(0.0, r.get("nan"), "NaN reached an output:\n" + failures);
        assertEquals(0, p.exitValue(), "exit status of the soak:\n" + tail(output));
        // it really ran: the audio output and the haptic loop worked for most of the time, the chaos thread called
        assertTrue(r.get("audioBlocks") > 0.5 * SECONDS * 44100 / Soak.DEFAULT_BUFFER,
                "audio blocks: " + r.get("audioBlocks") + "\n" + tail(output));
        assertTrue(r.get("hapticTicks") > 0.5 * SECONDS * 1000, "haptic ticks: " + r.get("hapticTicks"));
        assertTrue(r.get("calls") > 1000, "calls: " + r.get("calls"));
        System.out.println(output.substring(output.lastIndexOf("soak finished")));
    }

    private static String read(Path log) throws IOException {
        return Files.exists(log) ? Files.readString(log, StandardCharsets.UTF_8) : "";
    }

    /** Parses the last line: SOAK RESULT key=value ... */
    static Map<String, Double> result(String output) {
        Matcher line = Pattern.compile("SOAK RESULT (.*)").matcher(output);
        if (!line.find()) {
            fail("the soak printed no result line:\n" + tail(output));
        }
        Map<String, Double> r = new HashMap<>();
        Matcher kv = Pattern.compile("(\\w+)=([-0-9.]+)").matcher(line.group(1));
        while (kv.find()) {
            r.put(kv.group(1), Double.parseDouble(kv.group(2)));
        }
        for (String k : new String[] {"escapes", "hangs", "nan", "audioBlocks", "hapticTicks", "calls"}) {
            assertTrue(r.containsKey(k), "no " + k + " in the result line: " + line.group(0));
        }
        return r;
    }

    /** The summary's failure list (one line per kind, with the defect tag), or the output's end. */
    private static String failures(String output) {
        int at = output.indexOf("failures by kind");
        return at >= 0 ? output.substring(at) : tail(output);
    }

    private static String tail(String s) {
        return s.length() <= 6000 ? s : "...\n" + s.substring(s.length() - 6000);
    }

    /** The result parser must see a failure: a line with escapes is read as such (the check can fail). */
    @Test
    void theResultLineIsParsed() {
        Map<String, Double> r = result("x\nSOAK RESULT escapes=3 hangs=0 nan=1 lateBlocks=2 missedTicks=0 calls=10 "
                + "audioBlocks=5 modelSteps=9 hapticTicks=7 seconds=1.0\n");
        assertEquals(3.0, r.get("escapes"));
        assertEquals(1.0, r.get("nan"));
        assertEquals(7.0, r.get("hapticTicks"));
    }
}
