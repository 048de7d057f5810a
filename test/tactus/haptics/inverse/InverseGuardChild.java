package tactus.haptics.inverse;

import java.net.URI;

import tactus.haptics.HapticLoop;

/**
 * A sketch-like JVM for InverseGuardTest: a HapticLoop pushing 1 N along x on a guarded Inverse3 through the service
 * at args[0]; prints "READY guarded|unguarded", then waits to be killed, stopped or terminated.
 */
public final class InverseGuardChild {
    private InverseGuardChild() {
    }

    /** Runs the child. */
    public static void main(String[] args) throws Exception {
        Inverse3Device dev = Inverse3Device.openGuarded(URI.create(args[0]), 20_000);
        HapticLoop loop = new HapticLoop(dev, new Inverse3LoopTest.ConstantAvatar(1, 0, 0));
        loop.useRealUnits();
        loop.start();
        while (loop.ticks() < 200) {
            Thread.sleep(5);
        }
        System.out.println("READY " + (dev.isGuarded() ? "guarded" : "unguarded"));
        System.out.flush();
        Thread.sleep(60_000);
    }
}
