package tactus.haptics;

import com.fazecast.jSerialComm.SerialPort;
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
 * The board's side of the {@link MotorGuard}: starts the guard process when a board opens a serial port, tells
 * it the port and each device's setup, and says {@code clean} when the board closed with the torques zeroed.
 * Starting or talking to the guard never fails the board: a failure prints one warning and the board runs
 * without the guard.
 */
final class MotorGuardLink {
    /** System property that turns the guard off when "false" (default on). */
    static final String PROPERTY = "tactus.motorGuard";
    /** The link of a board without a guard (in-process transports, or the guard turned off). */
    static final MotorGuardLink NONE = new MotorGuardLink(null, null);

    private static volatile boolean enabled = !"false".equalsIgnoreCase(System.getProperty(PROPERTY, "true"));
    /** JVM options of the guard: small heap, no JIT, no perf data (it waits, then sends a few bytes). */
    private static final String[] JVM_OPTIONS = {"-Xint", "-XX:+UseSerialGC", "-Xms4m", "-Xmx16m", "-Xss256k",
            "-XX:-UsePerfData", "-Djava.awt.headless=true"};
    /** Properties passed on to the guard so that it finds jSerialComm's native library as the sketch did. */
    private static final String[] INHERITED_PROPERTIES = {"java.io.tmpdir", "fazecast.jSerialComm.appid",
            "jSerialComm.library.path", "jSerialComm.library.randomizeNativeName", "os.arch_full"};

    private final Process process;
    private OutputStream toGuard;

    private MotorGuardLink(Process process, OutputStream toGuard) {
        this.process = process;
        this.toGuard = toGuard;
    }

    /** Turns the guard on or off for boards opened from now on (the property {@value #PROPERTY} sets the default). */
    static void setEnabled(boolean on) {
        enabled = on;
    }

    /** True if boards opened from now on start a guard. */
    static boolean isEnabled() {
        return enabled;
    }

    /** Starts a guard for a board on a serial transport; {@link #NONE} for other transports or when turned off. */
    static MotorGuardLink watch(Transport transport) {
        if (!enabled || !(transport instanceof SerialTransport)) {
            return NONE;
        }
        SerialTransport serial = (SerialTransport) transport;
        try {
            ProcessBuilder pb = new ProcessBuilder(command());
            Map<String, String> env = pb.environment();
            env.remove("JAVA_TOOL_OPTIONS");   // a debugger agent there would make the guard fail to start
            env.remove("_JAVA_OPTIONS");
            env.remove("JDK_JAVA_OPTIONS");
            pb.redirectOutput(ProcessBuilder.Redirect.DISCARD);
            pb.redirectError(ProcessBuilder.Redirect.INHERIT);
            Process p = pb.start();
            MotorGuardLink link = new MotorGuardLink(p, p.getOutputStream());
            link.send(MotorGuard.HELLO + "\nport " + serial.baudRate() + " " + serial.describe());
            return link;
        } catch (IOException | RuntimeException e) {
            System.err.println("Tactus: could not start the motor guard (" + e + "); the motors are zeroed only "
                    + "if the sketch closes the board or its JVM runs its shutdown hooks");
            return NONE;
        }
    }

    /** Tells the guard a device's setup: its id, the length of its write message and of the board's reply. */
    void deviceConfigured(Device device) {
        byte[] zeros = device.zeroMessage();
        if (zeros != null) {
            send("device " + (device.id() & 0xFF) + " " + zeros.length + " " + device.replyBytes());
        }
    }

    /**
     * Ends the link. With motorsZeroed the guard exits at once; otherwise it zeroes the motors itself now
     * (the board has let go of the port).
     */
    synchronized void release(boolean motorsZeroed) {
        if (toGuard == null) {
            return;
        }
        if (motorsZeroed) {
            send("clean");
        }
        try {
            toGuard.close();
        } catch (IOException ignored) {
            // the guard is gone
        }
        toGuard = null;
    }

    /** The guard process, or null for {@link #NONE} (for tests). */
    Process process() {
        return process;
    }

    private synchronized void send(String lines) {
        if (toGuard == null) {
            return;
        }
        try {
            toGuard.write((lines + "\n").getBytes(StandardCharsets.UTF_8));
            toGuard.flush();
        } catch (IOException e) {
            System.err.println("Tactus: the motor guard is gone (" + e.getMessage() + ")");
            toGuard = null;
        }
    }

    /** The command line that starts a guard: this JVM's java, small-footprint options, Tactus and jSerialComm. */
    static List<String> command() {
        String java = ProcessHandle.current().info().command()
                .orElse(Paths.get(System.getProperty("java.home"), "bin", "java").toString());
        List<String> cmd = new ArrayList<>();
        cmd.add(java);
        for (String o : JVM_OPTIONS) {
            cmd.add(o);
        }
        for (String k : INHERITED_PROPERTIES) {
            String v = System.getProperty(k);
            if (v != null) {
                cmd.add("-D" + k + "=" + v);
            }
        }
        cmd.add("-cp");
        cmd.add(classPath());
        cmd.add(MotorGuard.class.getName());
        return cmd;
    }

    private static String classPath() {
        Set<String> entries = new LinkedHashSet<>();
        for (Class<?> c : new Class<?>[] {MotorGuard.class, SerialPort.class}) {
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
        return String.join(File.pathSeparator, entries);
    }
}
