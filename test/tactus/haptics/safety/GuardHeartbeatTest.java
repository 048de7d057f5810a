package tactus.haptics.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.sun.management.ThreadMXBean;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Paths;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The memory shared by a sketch's board and its motor guard: what one side stores the other reads, the file's
 * name can go while both keep their mapping, and a heartbeat costs the haptic thread no allocation.
 */
@Timeout(30)
class GuardHeartbeatTest {

    @Test
    void whatOneSideStoresTheOtherReads() throws Exception {
        GuardHeartbeat board = GuardHeartbeat.create();
        GuardHeartbeat guard = GuardHeartbeat.open(board.path());
        assertTrue(Files.exists(Paths.get(board.path())));
        board.unlink();   // both keep their mapping
        assertFalse(Files.exists(Paths.get(board.path())));
        assertEquals(GuardHeartbeat.STATE_WAITING, board.state());
        guard.setState(GuardHeartbeat.STATE_READY);
        assertEquals(GuardHeartbeat.STATE_READY, board.state());
        assertFalse(guard.armed());
        board.arm(true);
        board.beat(12345L);
        assertTrue(guard.armed());
        assertEquals(12345L, guard.heartbeat());
        assertEquals(0, board.guardWrites());
        guard.countGuardWrite();
        guard.countGuardWrite();
        assertEquals(2, board.guardWrites());
        board.arm(false);
        assertFalse(guard.armed());
    }

    @Test
    void aFileThatIsNotAHeartbeatIsRefused() throws Exception {
        java.nio.file.Path p = Files.createTempFile("not-a-heartbeat", ".hb");
        try {
            Files.write(p, new byte[GuardHeartbeat.SIZE]);
            try {
                GuardHeartbeat.open(p.toString());
                throw new AssertionError("a file without the magic number was taken");
            } catch (java.io.IOException expected) {
                assertTrue(expected.getMessage().contains("not a tactus heartbeat file"), expected.getMessage());
            }
        } finally {
            Files.deleteIfExists(p);
        }
    }

    @Test
    void aHeartbeatAllocatesNothing() throws Exception {
        ThreadMXBean mx = (ThreadMXBean) ManagementFactory.getThreadMXBean();
        mx.setThreadAllocatedMemoryEnabled(true);
        GuardHeartbeat hb = GuardHeartbeat.create();
        hb.unlink();
        long sink = 0;
        long best = Long.MAX_VALUE;
        for (int round = 0; round < 20; round++) {   // the first rounds link the VarHandle and compile
            long bytes0 = mx.getThreadAllocatedBytes(Thread.currentThread().getId());
            for (int i = 0; i < 100_000; i++) {
                hb.beat(i);
                hb.arm((i & 1) == 0);
                sink += hb.guardWrites();
            }
            best = Math.min(best, mx.getThreadAllocatedBytes(Thread.currentThread().getId()) - bytes0);
        }
        assertEquals(0, best, "bytes allocated by 100,000 heartbeats (best of 20 rounds); " + sink);
    }
}
