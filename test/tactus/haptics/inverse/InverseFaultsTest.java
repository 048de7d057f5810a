package tactus.haptics.inverse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.UnaryOperator;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import tactus.haptics.HaplyLinkException;
import tactus.haptics.HapticLoop;
import tactus.haptics.emulator.InverseServiceEmulator;

/**
 * What a loop on the Inverse Service says when the service's messages go wrong: each fault, injected into the
 * emulator's frames, ends with a message naming what arrived, not with a timeout that blames the device.
 */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class InverseFaultsTest {
    private static final String POSITION = "\"cursor_position\":\\{[^}]*\\}";

    /** Runs a loop until it fails after the fault is switched on; returns its failure message. */
    private static String failureAfter(UnaryOperator<String> fault) {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            AtomicBoolean on = new AtomicBoolean();
            emu.setRewrite(f -> on.get() ? fault.apply(f) : f);
            Inverse3Device dev = Inverse3Device.open(emu.uri(), 10_000);
            Inverse3LoopTest.ConstantAvatar a = new Inverse3LoopTest.ConstantAvatar(0.5, 0, 0);
            HapticLoop loop = new HapticLoop(dev, a);
            loop.useRealUnits();
            loop.start();
            Inverse3LoopTest.await(() -> loop.ticks() > 100, 20_000, "100 ticks: " + loop.failure());
            assertTrue(loop.failure() == null, "no failure before the fault: " + loop.failure());
            on.set(true);
            Inverse3LoopTest.await(() -> loop.failure() != null, 20_000, "a failure after the fault");
            loop.stop();
            // the zero force went out before the failure was set; the emulator applies it on its own thread
            Inverse3LoopTest.await(() -> {
                double[] f = emu.force();
                return f[0] == 0 && f[1] == 0 && f[2] == 0;
            }, 5_000, "the force stopped: " + java.util.Arrays.toString(emu.force()));
            dev.close();
            return loop.failure();
        }
    }

    private static String connectFailure(UnaryOperator<String> fault) {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            emu.setRewrite(fault);
            HaplyLinkException e = assertThrows(HaplyLinkException.class, () -> Inverse3Device.open(emu.uri(), 20_000));
            return e.getMessage();
        }
    }

    @Test
    void framesWithNaNLiteralsAreReportedAsUnreadableNotAsASilentDevice() {
        String m = failureAfter(f -> f.replaceAll(POSITION, "\"cursor_position\":{\"x\":NaN,\"y\":NaN,\"z\":NaN}"));
        assertTrue(m.contains("cannot read") && m.contains("NaN"), m);
        assertFalse(m.contains("no state"), m);
    }

    @Test
    void nullPositionsAreReportedAsNullPositions() {
        String m = failureAfter(f -> f.replaceAll(POSITION, "\"cursor_position\":null"));
        assertTrue(m.contains("cursor_position is null"), m);
        assertFalse(m.contains("no state"), m);
    }

    @Test
    void aPositionBeyondReachStopsTheForceWithAMessage() {
        String m = failureAfter(f -> f.replaceAll(POSITION, "\"cursor_position\":{\"x\":1e300,\"y\":0.0,\"z\":0.1}"));
        assertTrue(m.contains("1.0E300") && m.contains("reach") && m.contains("force is stopped"), m);
    }

    @Test
    void aDeviceTheServiceNoLongerListsIsNamed() {
        String m = failureAfter(f -> f.replaceAll("\"inverse3\":\\[.*\\],\"verse_grip\"", "\"inverse3\":[],\"verse_grip\""));
        assertTrue(m.contains("no longer lists the Inverse3 " + InverseServiceEmulator.DEVICE_ID), m);
    }

    @Test
    void connectingToUnreadableFramesSaysSoAtOnce() {
        long t0 = System.nanoTime();
        String m = connectFailure(f -> f.replaceAll(POSITION, "\"cursor_position\":{\"x\":NaN}"));
        assertTrue(m.contains("cannot read") && m.contains("NaN"), m);
        assertFalse(m.contains("within 20000 ms"), "not the timeout: " + m);
        assertTrue(System.nanoTime() - t0 < 15_000_000_000L, "well before the 20 s timeout");
    }

    @Test
    void anEmptyInverse3ListIsReportedAsSuchNotAsATimeout() {
        String m = connectFailure(f -> f.replaceAll("\"inverse3\":\\[.*\\],\"verse_grip\"", "\"inverse3\":[],\"verse_grip\""));
        assertTrue(m.contains("lists no Inverse3"), m);
    }

    @Test
    void anUnknownDeviceTypeIsRefusedWithItsName() {
        String m = connectFailure(f -> f.replace("\"type\":\"inverse3\"", "\"type\":\"inverse9\"")
                .replace("\"device_type\":4", "\"device_type\":9"));
        assertTrue(m.contains("\"inverse9\"") && m.contains("does not know"), m);
    }

    @Test
    void knownTypesAndHandednessPassTheConnection() {
        for (String type : InverseServiceClient.KNOWN_TYPES) {
            try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
                emu.setRewrite(f -> f.replace("\"type\":\"inverse3\"", "\"type\":\"" + type + "\""));
                Inverse3Device d = Inverse3Device.open(emu.uri(), 10_000);
                assertEquals(type, d.kind());
                d.close();
            }
        }
    }
}
