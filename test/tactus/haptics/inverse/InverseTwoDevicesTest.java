package tactus.haptics.inverse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import tactus.haptics.AvatarLink;
import tactus.haptics.HaplyLinkException;
import tactus.haptics.HapticLoop;
import tactus.haptics.emulator.Hand3D;
import tactus.haptics.emulator.InverseServiceEmulator;
import tactus.haptics.emulator.SimulatedInverse3;

/** Two Inverse3s on one service: each connection reads and pushes the device it chose, by id, index or hand. */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class InverseTwoDevicesTest {
    private static final String OTHER = "0A11";

    /** A wall at model x = 0.04 m pushing back with 50 N/m from the side of lower x: the force tells the position. */
    static final class WallAvatar implements AvatarLink {
        volatile double x = Double.NaN;

        @Override
        public void setTarget(double px, double py, double pz) {
            x = px;
        }

        @Override
        public void takeForce(double[] out) {
            out[0] = 50 * (0.04 - x);
            out[1] = 0;
            out[2] = 0;
        }

        @Override
        public void step(int n) {
        }
    }

    private static SimulatedInverse3 heldAt(double x, double y, double z) {
        SimulatedInverse3 s = new SimulatedInverse3();
        s.setHand(Hand3D.scripted((t, out) -> {
            out[0] = x;
            out[1] = y;
            out[2] = z;
        }));
        return s;
    }

    private static InverseServiceEmulator twoDevicesOtherFirst() {
        double[] h = SimulatedInverse3.HOME;
        InverseServiceEmulator emu = InverseServiceEmulator.start(0, heldAt(h[0], h[1], h[2]));
        emu.addInverse3(OTHER, "left", heldAt(h[0] + 0.09, h[1], h[2]), true);
        return emu;
    }

    @Test
    void withAnotherInverse3ListedFirstTheForcesGoToOursComputedFromOurPosition() {
        double[] h = SimulatedInverse3.HOME;
        try (InverseServiceEmulator emu = twoDevicesOtherFirst()) {
            emu.setRecording(true);
            Inverse3Device dev = Inverse3Device.open(emu.uri(), 10_000, Inverse3Choice.byId(InverseServiceEmulator.DEVICE_ID));
            assertEquals(InverseServiceEmulator.DEVICE_ID, dev.deviceId());
            assertEquals("right", dev.handedness());
            WallAvatar a = new WallAvatar();
            HapticLoop loop = new HapticLoop(dev, a);
            loop.useRealUnits();
            loop.start();
            Inverse3LoopTest.await(() -> loop.ticks() > 300, 20_000, "300 ticks: " + loop.failure());
            loop.stop();
            assertNull(loop.failure());
            assertEquals(h[0], a.x, 1e-3, "the loop read our device's x, not the other's (" + (h[0] + 0.09) + ")");
            double expected = 50 * (0.04 - h[0]);
            double[] ours = new double[3];
            emu.device().force(ours);
            double[] other = new double[3];
            emu.device(OTHER).force(other);
            assertEquals(0, other[0], 0, "nothing pushed the other device");
            int near = 0;
            for (double[] f : emu.receivedForces()) {
                near += Math.abs(f[0] - expected) < 0.05 ? 1 : 0;
            }
            assertTrue(near > 100, near + " forces of about " + expected + " N reached our device (from our position)");
            dev.close();
        }
    }

    @Test
    void byIndexAndByHandednessPickTheListedDeviceAndFollowItsId() {
        try (InverseServiceEmulator emu = twoDevicesOtherFirst()) {
            Inverse3Device first = Inverse3Device.open(emu.uri(), 10_000, Inverse3Choice.byIndex(0));
            Inverse3Device right = Inverse3Device.open(emu.uri(), 10_000, Inverse3Choice.byHandedness("right"));
            Inverse3Device left = Inverse3Device.open(emu.uri(), 10_000, Inverse3Choice.byHandedness("left"));
            assertEquals(OTHER, first.deviceId());
            assertEquals(InverseServiceEmulator.DEVICE_ID, right.deviceId());
            assertEquals(OTHER, left.deviceId());
            assertEquals("left", left.handedness());
            InverseState s = new InverseState();
            left.readState(s);
            assertEquals(SimulatedInverse3.HOME[0] + 0.09, s.px, 1e-3, "the left device's own position");
            first.close();
            right.close();
            left.close();
        }
    }

    @Test
    void aChoiceTheServiceDoesNotListIsRefusedWithTheDevicesItLists() {
        try (InverseServiceEmulator emu = twoDevicesOtherFirst()) {
            HaplyLinkException e = assertThrows(HaplyLinkException.class,
                    () -> Inverse3Device.open(emu.uri(), 10_000, Inverse3Choice.byId("FFFF")));
            assertTrue(e.getMessage().contains("FFFF") && e.getMessage().contains(OTHER)
                    && e.getMessage().contains(InverseServiceEmulator.DEVICE_ID), e.getMessage());
            e = assertThrows(HaplyLinkException.class, () -> Inverse3Device.open(emu.uri(), 10_000, Inverse3Choice.byIndex(2)));
            assertTrue(e.getMessage().contains("number 2"), e.getMessage());
        }
    }
}
