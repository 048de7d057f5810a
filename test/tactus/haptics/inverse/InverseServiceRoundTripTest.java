package tactus.haptics.inverse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.ServerSocket;
import java.net.URI;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import tactus.haptics.HaplyLinkException;
import tactus.haptics.emulator.InverseServiceEmulator;
import tactus.haptics.emulator.SimulatedInverse3;

/** Our Inverse Service client against our emulator: handshake, snapshot, forces, state, VerseGrip, endings. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class InverseServiceRoundTripTest {

    /** Sends a force and waits (at most 2 s) for the frame that answers it; returns the new frame number. */
    static long exchange(InverseServiceClient c, InverseState s, double fx, double fy, double fz) {
        long before = c.read(s);
        long deadline = System.nanoTime() + 2_000_000_000L;
        while (!c.sendForce(fx, fy, fz)) {
            assertTrue(System.nanoTime() < deadline, "the socket did not take the message");
            Thread.onSpinWait();
        }
        long f;
        while ((f = c.read(s)) == before) {
            assertTrue(System.nanoTime() < deadline, "no frame answered the message");
            Thread.onSpinWait();
        }
        return f;
    }

    @Test
    void theHandshakeAndTheSnapshotNameTheDevice() {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0);
             InverseServiceClient c = InverseServiceClient.connect(emu.uri(), 3000)) {
            InverseState s = new InverseState();
            c.read(s);
            assertEquals(InverseServiceEmulator.DEVICE_ID, s.deviceId);
            assertEquals("inverse3", s.deviceType);
            assertEquals("right", s.handedness);
            assertTrue(s.snapshotSeen && s.ready && s.calibrated);
            assertEquals(SimulatedInverse3.HOME[1], s.py, 1e-12);
            exchange(c, s, 0, 0, 0);   // the snapshot is sent on connect, maybe before the handshake was read
            assertEquals(InverseServiceClient.PROFILE, emu.lastProfile(), "the first message carries the session's profile");
            assertTrue(emu.firstMessagesHadSession());
            for (int i = 0; i < 20; i++) {
                exchange(c, s, 0, 0, 0);
            }
            assertFalse(emu.laterMessagesHadProfile(), "only the first message carries the handshake");
            assertEquals(21, emu.forceCommands());
        }
    }

    @Test
    void aForceArrivesExactlyAndMovesTheHandle() {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            emu.setLockstep(1e-3);
            emu.setRecording(true);
            try (InverseServiceClient c = InverseServiceClient.connect(emu.uri(), 3000)) {
                InverseState s = new InverseState();
                for (int i = 0; i < 100; i++) {
                    exchange(c, s, 0.5, -0.25, 0.125 + i * 1e-4);
                }
                List<double[]> got = emu.receivedForces();
                assertEquals(100, got.size());
                for (int i = 0; i < 100; i++) {
                    assertEquals(0.5, got.get(i)[0], 0);
                    assertEquals(-0.25, got.get(i)[1], 0);
                    assertEquals(0.125 + i * 1e-4, got.get(i)[2], 0, "the number survives the text exactly");
                }
                // 0.1 s of a constant force on 0.25 kg with 1 N s/m of damping: x = F/b (t - tau (1 - e^(-t/tau)))
                double tau = 0.25 / 1.0;
                double expected = 0.5 / 1.0 * (0.1 - tau * (1 - Math.exp(-0.1 / tau)));
                assertEquals(SimulatedInverse3.HOME[0] + expected, s.px, 0.02 * expected);
                assertTrue(s.vx > 0 && s.vy < 0 && s.vz > 0, "the velocity follows the force: " + s);
                assertEquals(0.5, s.fx, 0, "the service reports the force it renders");
                double[] p = new double[3];
                emu.device().position(p);
                assertEquals(p[0], s.px, 0, "the frame carries the emulator's position");
                List<double[]> sent = emu.sentPositions();
                assertArrayEqualsExact(sent.get(sent.size() - 1), new double[] {s.px, s.py, s.pz});
                assertTrue(c.roundTripCount() >= 99);
            }
        }
    }

    private static void assertArrayEqualsExact(double[] a, double[] b) {
        for (int i = 0; i < 3; i++) {
            assertEquals(a[i], b[i], 0);
        }
    }

    @Test
    void closingSendsZeroForceFirst() {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            emu.setRecording(true);
            InverseServiceClient c = InverseServiceClient.connect(emu.uri(), 3000);
            InverseState s = new InverseState();
            exchange(c, s, 2, 0, 0);
            c.close();
            long deadline = System.nanoTime() + 2_000_000_000L;
            while (emu.zeroedOnDisconnect() == 0 && System.nanoTime() < deadline) {
                Thread.yield();   // the emulator reads the zero force, then the close
            }
            List<double[]> got = emu.receivedForces();
            double[] last = got.get(got.size() - 1);
            assertEquals(0, last[0], 0, "the last force the service got from us is zero");
            assertEquals(0, last[1], 0);
            assertEquals(0, last[2], 0);
            assertThrows(HaplyLinkException.class, () -> c.sendForce(1, 0, 0));
        }
    }

    @Test
    void aForceSentWhileAnotherThreadClosesNeverFollowsTheZeroForce() throws Exception {
        // the haptic thread keeps sending while the sketch closes (beside a CPU hog a sender that checked "open" just
        // before close() once wrote its force after the zero); the moment of close() varies from run to run. The sender
        // floods the service (thousands of messages in a few ms); when the emulator is still answering that backlog
        // after close()'s 250 ms, close() aborts and the reset may discard the tail, the zero among it: the order
        // cannot be read from what the service got, and its zero on disconnect is what stops the force
        int judged = 0;
        for (int run = 0; run < 20; run++) {
            try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
                emu.setRecording(true);
                InverseServiceClient c = InverseServiceClient.connect(emu.uri(), 3000);
                InverseState s = new InverseState();
                exchange(c, s, 2, 0, 0);
                java.util.concurrent.atomic.AtomicBoolean stop = new java.util.concurrent.atomic.AtomicBoolean();
                Thread sender = new Thread(() -> {
                    while (!stop.get()) {
                        try {
                            c.sendForce(1, 2, 3);
                        } catch (HaplyLinkException e) {
                            return;   // closed: what the loop sees next
                        }
                        Thread.yield();
                    }
                }, "racing-sender");
                sender.start();
                Thread.sleep(1 + run % 7);
                c.close();
                stop.set(true);
                sender.join(2_000);
                long deadline = System.nanoTime() + 2_000_000_000L;
                while (emu.zeroedOnDisconnect() == 0 && System.nanoTime() < deadline) {
                    Thread.yield();
                }
                assertTrue(emu.zeroedOnDisconnect() > 0, "run " + run + ": the service zeroed the force on disconnect");
                if (!c.peerClosedBeforeAbort()) {
                    continue;
                }
                judged++;
                List<double[]> got = emu.receivedForces();
                double[] last = got.get(got.size() - 1);
                assertEquals(0, last[0] * last[0] + last[1] * last[1] + last[2] * last[2], 0,
                        "run " + run + ": the last force the service got is zero, after " + got.size() + " forces; zero written: "
                        + c.closedAfterZero() + ": " + got.stream().map(java.util.Arrays::toString)
                        .collect(java.util.stream.Collectors.joining(" ")));
            }
        }
        assertTrue(judged >= 5, judged + " of 20 runs closed after the service had read everything");
    }

    @Test
    void anAbsentServiceIsNamedQuicklyAndClearly() throws Exception {
        int port;
        try (ServerSocket free = new ServerSocket(0)) {
            port = free.getLocalPort();
        }
        long t0 = System.nanoTime();
        HaplyLinkException e = assertThrows(HaplyLinkException.class,
                () -> InverseServiceClient.connect(URI.create("ws://localhost:" + port), 2000));
        long ms = (System.nanoTime() - t0) / 1_000_000;
        assertTrue(e.getMessage().contains("no Haply Inverse Service at ws://localhost:" + port), e.getMessage());
        assertTrue(e.getMessage().contains("Haply Hub"), e.getMessage());
        assertTrue(ms < 3000, "took " + ms + " ms");
    }

    @Test
    void somethingElseOnThePortIsNamed() throws Exception {
        // an HTTP server that does not upgrade: our emulator answers a plain GET with 404; a raw socket that never
        // answers must time out within the bound
        try (ServerSocket mute = new ServerSocket(0)) {
            long t0 = System.nanoTime();
            HaplyLinkException e = assertThrows(HaplyLinkException.class,
                    () -> InverseServiceClient.connect(URI.create("ws://localhost:" + mute.getLocalPort()), 500));
            long ms = (System.nanoTime() - t0) / 1_000_000;
            assertTrue(ms < 3000, "took " + ms + " ms: " + e.getMessage());
            assertNotNull(e.getMessage());
        }
    }

    @Test
    void aDroppedSocketIsLostWithAMessageAndNeverHangs() {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0);
             InverseServiceClient c = InverseServiceClient.connect(emu.uri(), 3000)) {
            InverseState s = new InverseState();
            exchange(c, s, 0.1, 0, 0);
            emu.dropConnections();
            long deadline = System.nanoTime() + 2_000_000_000L;
            while (c.lostReason() == null && System.nanoTime() < deadline) {
                c.sendForce(0.1, 0, 0);   // a send may be what notices it
                Thread.yield();
            }
            assertNotNull(c.lostReason(), "the client noticed the dropped socket");
            HaplyLinkException e = assertThrows(HaplyLinkException.class, () -> c.sendForce(0, 0, 0));
            assertTrue(e.getMessage().contains("Inverse Service"), e.getMessage());
            long t0 = System.nanoTime();
            c.close();
            assertTrue(System.nanoTime() - t0 < 1_000_000_000L, "close is bounded");
            deadline = System.nanoTime() + 2_000_000_000L;
            while (emu.zeroedOnDisconnect() == 0 && System.nanoTime() < deadline) {
                Thread.yield();
            }
            assertEquals(1, emu.zeroedOnDisconnect(), "the emulator zeroes the force of a client that vanished");
            double[] f = new double[3];
            emu.device().force(f);
            assertEquals(0, f[0], 0);
        }
    }

    @Test
    void aServiceThatStopsIsNamedAndAReconnectWorks() {
        InverseServiceEmulator emu = InverseServiceEmulator.start(0);
        int port = emu.port();
        InverseServiceClient c = InverseServiceClient.connect(emu.uri(), 3000);
        exchange(c, new InverseState(), 0, 0, 0);
        emu.close();
        long deadline = System.nanoTime() + 2_000_000_000L;
        while (c.lostReason() == null && System.nanoTime() < deadline) {
            Thread.yield();
        }
        assertNotNull(c.lostReason());
        assertTrue(c.lostReason().contains("closed the connection (code 1001"), c.lostReason());
        c.close();
        // the service restarts on the same port: a new client connects
        try (InverseServiceEmulator again = InverseServiceEmulator.start(port);
             InverseServiceClient d = InverseServiceClient.connect(again.uri(), 3000)) {
            exchange(d, new InverseState(), 0, 0, 0);
            assertEquals(1, again.forceCommands());
        }
    }

    @Test
    void theVerseGripsOrientationAndButtonsAreRead() {
        for (String kind : new String[] {"verse_grip", "wireless_verse_grip"}) {
            try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
                emu.setVerseGrip(kind);
                try (InverseServiceClient c = InverseServiceClient.connect(emu.uri(), 3000)) {
                    InverseState s = new InverseState();
                    exchange(c, s, 0, 0, 0);
                    assertEquals(InverseServiceEmulator.GRIP_ID, s.gripId, kind);
                    assertEquals(kind, s.gripKind);
                    assertFalse(s.buttonA);
                    double h = Math.sqrt(0.5);
                    emu.setGripOrientation(h, 0, h, 0);
                    emu.setButtons(true, true, false);
                    exchange(c, s, 0, 0, 0);
                    assertEquals(h, s.gripW, 1e-12, kind);
                    assertEquals(h, s.gripY, 1e-12, kind);
                    assertTrue(s.buttonA, kind);
                    assertEquals(kind.equals("wireless_verse_grip"), s.buttonB, kind + ": the wired grip has one button");
                    emu.setVerseGrip(null);
                    exchange(c, s, 0, 0, 0);
                    assertEquals(null, s.gripId, "a grip that is no longer listed is gone");
                }
            }
        }
    }
}
