package tactus.haptics.inverse;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.net.URI;
import java.nio.charset.StandardCharsets;

import tactus.haptics.HapticLoop;

/**
 * A sketch-like JVM for InverseShutdownTest: a HapticLoop pushing 1 N on an Inverse3 through the service at args[0];
 * prints READY, then on "exit" calls System.exit without closing anything; the parent may also kill it.
 */
public final class InverseShutdownChild {
    private InverseShutdownChild() {
    }

    /** Runs the child. */
    public static void main(String[] args) throws Exception {
        Inverse3Device dev = Inverse3Device.open(URI.create(args[0]), 5000);
        HapticLoop loop = new HapticLoop(dev, new Inverse3LoopTest.ConstantAvatar(1, 0, 0));
        loop.useRealUnits();
        loop.start();
        while (loop.ticks() < 200) {
            Thread.sleep(5);
        }
        System.out.println("READY");
        System.out.flush();
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        String line = in.readLine();
        if ("exit".equals(line)) {
            System.exit(0);
        }
        Thread.sleep(60_000);
    }
}
