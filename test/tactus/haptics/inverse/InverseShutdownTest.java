package tactus.haptics.inverse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.File;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import tactus.haptics.emulator.Hand3D;
import tactus.haptics.emulator.InverseServiceEmulator;
import tactus.haptics.emulator.SimulatedInverse3;

/**
 * A JVM that drives an Inverse3 and ends: on System.exit its shutdown hook sends zero force before the socket
 * goes; on SIGKILL nothing in the JVM runs, the socket is closed by the operating system, and the force is zero
 * only because the service (here our emulator) zeroes it for a client that vanished.
 */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class InverseShutdownTest {

    private static Process child(InverseServiceEmulator emu) throws Exception {
        String java = System.getProperty("java.home") + File.separator + "bin" + File.separator + "java";
        Process p = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"),
                InverseShutdownChild.class.getName(), emu.uri().toString()).redirectErrorStream(true).start();
        Thread reaper = new Thread(() -> {
            try {
                p.waitFor(60, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                // the test is over
            }
            p.destroyForcibly();
        }, "inverse-shutdown-child-reaper");
        reaper.setDaemon(true);
        reaper.start();
        BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
        StringBuilder log = new StringBuilder();
        String line;
        while ((line = out.readLine()) != null && !line.equals("READY")) {
            log.append(line).append('\n');
        }
        assertEquals("READY", line, "child output:\n" + log);
        return p;
    }

    private static InverseServiceEmulator emulator() {
        InverseServiceEmulator emu = InverseServiceEmulator.start(0);
        emu.device().setHand(Hand3D.scripted((t, out) -> System.arraycopy(SimulatedInverse3.HOME, 0, out, 0, 3)));
        emu.setRecording(true);
        emu.setCommandHold(Long.MAX_VALUE);   // the 1 N stays on between the child's messages, however late
        return emu;
    }

    private static void awaitDisconnect(InverseServiceEmulator emu) throws InterruptedException {
        long deadline = System.nanoTime() + 5_000_000_000L;
        while (emu.zeroedOnDisconnect() == 0 && System.nanoTime() < deadline) {
            Thread.sleep(1);
        }
        assertEquals(1, emu.zeroedOnDisconnect(), "the connection ended");
    }

    @Test
    void systemExitSendsZeroForceFromTheShutdownHook() throws Exception {
        try (InverseServiceEmulator emu = emulator()) {
            Process p = child(emu);
            double[] f = new double[3];
            emu.device().force(f);
            assertEquals(1, f[0], 0, "the child pushes 1 N");
            OutputStream in = p.getOutputStream();
            in.write("exit\n".getBytes(StandardCharsets.UTF_8));
            in.flush();
            assertTrue(p.waitFor(20, TimeUnit.SECONDS), "the child ends");
            awaitDisconnect(emu);
            List<double[]> got = emu.receivedForces();
            assertEquals(0, got.get(got.size() - 1)[0], 0, "the last force the child sent was zero (its shutdown hook)");
        }
    }

    @Test
    void aKilledJvmLeavesTheForceToTheService() throws Exception {
        try (InverseServiceEmulator emu = emulator()) {
            Process p = child(emu);
            p.destroyForcibly();
            assertTrue(p.waitFor(20, TimeUnit.SECONDS), "the child ends");
            awaitDisconnect(emu);
            List<double[]> got = emu.receivedForces();
            assertEquals(1, got.get(got.size() - 1)[0], 0, "SIGKILL: the child's last force was 1 N; nothing in it ran");
            double[] f = new double[3];
            emu.device().force(f);
            assertEquals(0, f[0], 0, "zero only because the emulator zeroes the force of a vanished client");
        }
    }
}
