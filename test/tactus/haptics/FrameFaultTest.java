package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.transport.Transport;
import tactus.haptics.transport.WireFormat;

/** Malformed, partial and unexpected frames, and a board unplugged mid-run: the reader survives and counts. */
class FrameFaultTest {

    private static Device open(BoardEmulator emulator, Board board) {
        Device d = new Device((byte) 3, board);
        HaplyPreset.HAPLY_2018.configure(d);
        d.device_set_parameters();
        return d;
    }

    private static byte[] frame(int id, float a, float b) {
        byte[] f = new byte[9];
        f[0] = (byte) id;
        WireFormat.putFloat(f, 1, a);
        WireFormat.putFloat(f, 5, b);
        return f;
    }

    @Test
    void strayByteIsDetectedFlushedAndTheNextTickRecovers() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        try (Board board = new Board(emulator.connect())) {
            Device d = open(emulator, board);
            d.device_read_request();
            d.device_read_data();
            float[] good = d.get_device_angles();
            emulator.injectToHost(new byte[] {0x55});          // one stray byte before the next reply
            d.device_read_request();
            d.device_read_data();
            assertEquals(10, board.unexpectedBytes(), "the stray byte and the reply behind it");
            assertArrayEquals(good, d.get_device_angles(), "the previous values are kept");
            assertFalse(board.data_available(), "flushed");
            d.device_read_request();
            d.device_read_data();
            assertEquals(2, board.framesRead());
            assertArrayEquals(good, d.get_device_angles());
        }
    }

    @Test
    void aMisalignedFrameThatStartsWithTheRightIdIsNotDecoded() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        emulator.setLockstep(0.001);
        try (Board board = new Board(emulator.connect())) {
            Device d = open(emulator, board);
            d.device_read_request();
            d.device_read_data();
            float[] good = d.get_device_angles();
            emulator.injectToHost(new byte[] {3, 0x10, 0x20});   // 3 stray bytes, the first equal to the id
            d.device_read_request();
            d.device_read_data();                                 // 12 bytes: [3 10 20 | 3 a a a a b b] would decode
            assertArrayEquals(good, d.get_device_angles());
            assertEquals(12, board.unexpectedBytes());
            assertEquals(1, board.framesRead());
            d.device_read_request();
            d.device_read_data();
            assertEquals(2, board.framesRead());
            assertArrayEquals(good, d.get_device_angles());
        }
    }

    @Test
    void anAbsurdValueInAFrameIsRefused() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        try (Board board = new Board(emulator.connect())) {
            Device d = open(emulator, board);
            emulator.dropReplies(1);
            d.device_read_request();
            emulator.injectToHost(frame(3, Float.NaN, 1e30f));
            d.device_read_data();
            assertEquals(1, board.implausibleFrames());
            assertArrayEquals(new float[] {0f, 0f}, d.get_device_angles());
        }
    }

    @Test
    void unexpectedFrameOfAnotherDeviceIsRefused() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        try (Board board = new Board(emulator.connect())) {
            Device d = open(emulator, board);
            emulator.dropReplies(1);
            d.device_read_request();
            emulator.injectToHost(frame(7, 1f, 2f));           // a full frame, but for id 7
            d.device_read_data();
            assertEquals(1, board.idMismatches());
            assertArrayEquals(new float[] {0f, 0f}, d.get_device_angles(), "nothing was taken from it");
            d.device_read_request();
            d.device_read_data();
            assertArrayEquals(new float[] {180f, 0f}, d.get_device_angles());
        }
    }

    @Test
    void partialFrameTimesOutAndIsDropped() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        try (Board board = new Board(emulator.connect())) {
            board.setTimeoutMillis(5);
            Device d = open(emulator, board);
            emulator.dropReplies(1);
            d.device_read_request();
            emulator.injectToHost(new byte[] {3, 0, 0});       // the first 3 bytes of a frame, then nothing
            assertTrue(board.data_available());
            d.device_read_data();
            assertEquals(1, board.timeouts());
            assertEquals(3, board.bytesDiscarded());
            assertFalse(board.data_available());
            d.device_read_request();
            d.device_read_data();
            assertArrayEquals(new float[] {180f, 0f}, d.get_device_angles());
            assertEquals(1, board.framesRead());
        }
    }

    @Test
    void noReplyAtAllTimesOut() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        try (Board board = new Board(emulator.connect())) {
            board.setTimeoutMillis(3);
            Device d = open(emulator, board);
            emulator.dropReplies(1);
            d.device_read_request();
            d.device_read_data();
            assertEquals(1, board.timeouts());
            assertEquals(0, board.framesRead());
        }
    }

    @Test
    void aBoardThatStopsAnsweringIsDeclaredLost() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        Board board = new Board(emulator.connect());
        board.setTimeoutMillis(2);
        board.setLostAfterTimeouts(3);
        Device d = open(emulator, board);
        emulator.dropReplies(1000);
        d.device_read_request();
        d.device_read_data();
        d.device_read_request();
        d.device_read_data();
        assertFalse(board.isClosed());
        d.device_read_request();
        HaplyLinkException e = assertThrows(HaplyLinkException.class, d::device_read_data);
        assertTrue(e.getMessage().contains("no reply to 3 reads"), e.getMessage());
        assertTrue(board.isClosed());
    }

    @Test
    void unpluggedMidRunGivesAClearErrorAndAQuietClose() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        Board board = new Board(emulator.connect());
        Device d = open(emulator, board);
        for (int i = 0; i < 10; i++) {
            d.device_write_torques();
            d.device_read_data();
        }
        emulator.unplug();
        HaplyLinkException e = assertThrows(HaplyLinkException.class, d::device_write_torques);
        assertTrue(e.getMessage().contains("unplugged"), e.getMessage());
        assertTrue(e.getMessage().contains("USB"), e.getMessage());
        assertTrue(board.isClosed());
        assertTrue(board.lostReason().contains("emulator"));
        board.close();                                          // no throw
        assertThrows(HaplyLinkException.class, d::device_read_data);
        assertFalse(board.data_available());
    }

    @Test
    void firmwareReadsASplitCommandWrongWhichIsWhyCommandsGoOutWhole() {
        // what the firmware does if a host split a setup in two writes: the late single bytes read as 0xFF
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        Transport t = emulator.connect();
        byte[] setup = WireFormat.setup((byte) 3, new int[] {0, 0}, new int[] {0, 0},
                new float[] {180f, 0f}, new float[] {13824f, 13824f}, new int[0], new int[0]);
        try {
            t.write(setup, 0, 4);
            t.write(setup, 4, setup.length - 4);
        } catch (java.io.IOException e) {
            throw new AssertionError(e);
        }
        assertTrue(emulator.lateBytes() > 0);
    }

    @Test
    void aWriteForAnotherIdIsAnsweredWithTheIdAlone() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        try (Board board = new Board(emulator.connect())) {
            open(emulator, board);
            board.transmit((byte) 2, (byte) 9, null, new float[] {0f, 0f});
            assertEquals(1, emulator.foreignWrites());
            assertTrue(board.data_available());
            float[] r = board.receive((byte) 2, (byte) 9, 0);
            assertEquals(0, r.length);
            assertEquals(1, board.framesRead());
        }
    }
}
