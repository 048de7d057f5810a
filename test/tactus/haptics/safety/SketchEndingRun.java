package tactus.haptics.safety;

import static org.junit.jupiter.api.Assertions.assertTrue;

import com.sun.jdi.Bootstrap;
import com.sun.jdi.VMDisconnectedException;
import com.sun.jdi.VirtualMachine;
import com.sun.jdi.connect.AttachingConnector;
import com.sun.jdi.connect.Connector;
import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.PtyPair;
import tactus.haptics.transport.SerialTransport;
import tactus.haptics.Board;
import tactus.haptics.HaplyPreset;

/**
 * For the motor-guard tests: a sketch-like child JVM driving the board emulator over a socat pty pair (the
 * emulator in this JVM on one end, the child's {@link Board} on the other), which the test then ends in one
 * of the ways a sketch can end, timing how long the motors take to reach duty 0.
 */
final class SketchEndingRun implements AutoCloseable {
    private static final Pattern JDWP = Pattern.compile("Listening for transport dt_socket at address: (\\d+)");

    final PtyPair pty;
    final BoardEmulator emulator;
    final Process child;
    private final StringBuffer log = new StringBuffer();
    private final CountDownLatch ready = new CountDownLatch(1);
    private volatile String jdwpPort;
    private ProcessHandle guard;

    private SketchEndingRun(PtyPair pty, BoardEmulator emulator, Process child) {
        this.pty = pty;
        this.emulator = emulator;
        this.child = child;
        Thread reader = new Thread(this::readOutput, "sketch-ending-output");
        reader.setDaemon(true);
        reader.start();
    }

    /**
     * Starts the emulator on a new pty pair and a child JVM {@code prefix... java jvmOptions... -cp <test class
     * path> mainClass <host end> args...}, and waits (up to 20 s) until it prints READY with the motors driven.
     */
    static SketchEndingRun start(List<String> prefix, List<String> jvmOptions, String mainClass, String... args)
            throws Exception {
        PtyPair pty = PtyPair.open();
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        emulator.serve(SerialTransport.open(pty.boardEnd(), 0));
        List<String> cmd = new ArrayList<>(prefix);
        cmd.add(System.getProperty("java.home") + File.separator + "bin" + File.separator + "java");
        cmd.addAll(jvmOptions);
        cmd.add("-cp");
        cmd.add(System.getProperty("java.class.path"));
        cmd.add(mainClass);
        cmd.add(pty.hostEnd());
        cmd.addAll(List.of(args));
        Process child = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        SketchEndingRun run = new SketchEndingRun(pty, emulator, child);
        try {
            assertTrue(run.ready.await(20, TimeUnit.SECONDS), "the child prints READY; its output:\n" + run.log);
            long deadline = System.nanoTime() + 2_000_000_000L;
            while (!run.motorsDriven() && System.nanoTime() < deadline) {
                Thread.sleep(2);
            }
            run.guard = child.toHandle().descendants().filter(SketchEndingRun::isGuard).findFirst().orElse(null);
            assertTrue(run.motorsDriven(), "the child drives both motors (duty " + emulator.duty(1) + "/"
                    + emulator.duty(2) + "); its output:\n" + run.log);
        } catch (Throwable t) {
            run.close();
            throw t;
        }
        return run;
    }

    private static boolean isGuard(ProcessHandle h) {
        String[] args = h.info().arguments().orElse(new String[0]);
        return args.length > 0 && args[args.length - 1].equals(MotorGuard.class.getName());
    }

    /** True while both motors have a non-zero duty. */
    boolean motorsDriven() {
        return emulator.duty(1) != 0 && emulator.duty(2) != 0;
    }

    /**
     * Waits up to limitMs for both motors' duty to be 0; returns the milliseconds from startNanos to the first
     * moment seen so, or -1 if it did not happen.
     */
    double millisToZero(long startNanos, long limitMs) throws InterruptedException {
        long deadline = startNanos + limitMs * 1_000_000L;
        while (System.nanoTime() < deadline) {
            if (emulator.duty(1) == 0 && emulator.duty(2) == 0) {
                return (System.nanoTime() - startNanos) / 1e6;
            }
            Thread.sleep(0, 200_000);
        }
        return -1;
    }

    /** The motor guard process the child had started when it printed READY, if any. */
    Optional<ProcessHandle> guard() {
        return Optional.ofNullable(guard);
    }

    /** Sends one line to the child's standard input. */
    void tell(String line) throws IOException {
        child.getOutputStream().write((line + "\n").getBytes(StandardCharsets.UTF_8));
        child.getOutputStream().flush();
    }

    /** Does what the Processing editor's Stop button does: attaches over JDWP and calls {@code vm.exit(0)}. */
    VirtualMachine attach() throws Exception {
        assertTrue(jdwpPort != null, "the child runs under the JDWP agent; its output:\n" + log);
        AttachingConnector socket = null;
        for (AttachingConnector c : Bootstrap.virtualMachineManager().attachingConnectors()) {
            if (c.name().equals("com.sun.jdi.SocketAttach")) {
                socket = c;
            }
        }
        Map<String, Connector.Argument> a = socket.defaultArguments();
        a.get("hostname").setValue("127.0.0.1");
        a.get("port").setValue(jdwpPort);
        return socket.attach(a);
    }

    /** Ends an attached VM as the Stop button does (Processing's Runner.close: vm.exit(0)). */
    static void stopButton(VirtualMachine vm) {
        try {
            vm.exit(0);
        } catch (VMDisconnectedException e) {
            // the VM went first
        }
    }

    /** Everything the child (and the guard, which shares its standard error) printed so far. */
    String log() {
        return log.toString();
    }

    /** Waits up to ms for the child's output (and the guard's) to end. */
    boolean awaitOutputEnd(long ms) throws InterruptedException {
        long deadline = System.nanoTime() + ms * 1_000_000L;
        while (!outputEnded && System.nanoTime() < deadline) {
            Thread.sleep(5);
        }
        return outputEnded;
    }

    private volatile boolean outputEnded;

    private void readOutput() {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(child.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                log.append(line).append('\n');
                Matcher m = JDWP.matcher(line);
                if (m.find()) {
                    jdwpPort = m.group(1);
                }
                if (line.equals("READY")) {
                    ready.countDown();
                }
            }
        } catch (IOException ignored) {
            // the child is gone
        } finally {
            outputEnded = true;
        }
    }

    @Override
    public void close() {
        child.destroyForcibly();
        guard().ifPresent(ProcessHandle::destroyForcibly);
        emulator.close();
        pty.close();
    }
}
