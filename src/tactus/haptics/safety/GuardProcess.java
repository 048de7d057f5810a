package tactus.haptics.safety;

import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Paths;
import java.security.CodeSource;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * A guard process beside the sketch's JVM, as Tactus's guards start it (the 2DIY's {@link MotorGuard}, the
 * Inverse3's {@code tactus.haptics.inverse.InverseGuard}): the same {@code java} as this JVM with small-footprint
 * options and the class path of the classes it needs, without the agent options of the environment (a debugger
 * agent there would stop it from starting), its output discarded and its standard error this JVM's; this JVM
 * talks to it in lines on its standard input, whose end (however this JVM ends) is the guard's signal. Not for
 * sketches.
 */
public final class GuardProcess {
    private final Process process;
    private final String name;
    private OutputStream toGuard;

    private GuardProcess(Process process, String name) {
        this.process = process;
        this.name = name;
        this.toGuard = process.getOutputStream();
    }

    /**
     * The command line of a guard: this JVM's java, the options, the inherited system properties that are set
     * (as {@code -Dkey=value}), the class path of the given classes' code sources, and the main class.
     *
     * @throws IllegalStateException if a class has no code source
     */
    public static List<String> command(String mainClass, String[] options, String[] inheritedProperties,
                                       Class<?>... onClassPath) {
        String java = ProcessHandle.current().info().command()
                .orElse(Paths.get(System.getProperty("java.home"), "bin", "java").toString());
        List<String> cmd = new ArrayList<>();
        cmd.add(java);
        for (String o : options) {
            cmd.add(o);
        }
        for (String k : inheritedProperties) {
            String v = System.getProperty(k);
            if (v != null) {
                cmd.add("-D" + k + "=" + v);
            }
        }
        Set<String> entries = new LinkedHashSet<>();
        for (Class<?> c : onClassPath) {
            CodeSource cs = c.getProtectionDomain().getCodeSource();
            if (cs == null || cs.getLocation() == null) {
                throw new IllegalStateException("no code source for " + c.getName());
            }
            try {
                entries.add(Paths.get(cs.getLocation().toURI()).toString());
            } catch (java.net.URISyntaxException e) {
                throw new IllegalStateException("code source of " + c.getName() + ": " + e.getMessage(), e);
            }
        }
        cmd.add("-cp");
        cmd.add(String.join(File.pathSeparator, entries));
        cmd.add(mainClass);
        return cmd;
    }

    /** Starts a guard with this command line; name is what warnings call it ("the motor guard"). */
    public static GuardProcess start(List<String> command, String name) throws IOException {
        ProcessBuilder pb = new ProcessBuilder(command);
        Map<String, String> env = pb.environment();
        env.remove("JAVA_TOOL_OPTIONS");
        env.remove("_JAVA_OPTIONS");
        env.remove("JDK_JAVA_OPTIONS");
        pb.redirectOutput(ProcessBuilder.Redirect.DISCARD);
        pb.redirectError(ProcessBuilder.Redirect.INHERIT);
        return new GuardProcess(pb.start(), name);
    }

    /** The process. */
    public Process process() {
        return process;
    }

    /** Sends lines (a newline is added); after a failure (the guard is gone: one warning) or close, does nothing. */
    public synchronized void send(String lines) {
        if (toGuard == null) {
            return;
        }
        try {
            toGuard.write((lines + "\n").getBytes(StandardCharsets.UTF_8));
            toGuard.flush();
        } catch (IOException e) {
            System.err.println("Tactus: " + name + " is gone (" + e.getMessage() + ")");
            toGuard = null;
        }
    }

    /** True until {@link #closeInput()} (or a failed send). */
    public synchronized boolean isOpen() {
        return toGuard != null;
    }

    /** Closes the guard's standard input: the guard's signal that this JVM let go. */
    public synchronized void closeInput() {
        if (toGuard == null) {
            return;
        }
        try {
            toGuard.close();
        } catch (IOException ignored) {
            // the guard is gone
        }
        toGuard = null;
    }
}
