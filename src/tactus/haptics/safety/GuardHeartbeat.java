package tactus.haptics.safety;

import java.io.IOException;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.nio.MappedByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.nio.file.StandardOpenOption;

/**
 * A few words of memory shared between a sketch's JVM and its {@link MotorGuard} through a memory-mapped file, so
 * that the guard can tell a paused JVM (a debugger's breakpoint, SIGSTOP, a long pause) from a running one
 * without any I/O on the haptic path: a store to this memory is a plain memory write, no system call.
 *
 * <p>Each word has one writer. The sketch's JVM writes the heartbeat (the {@link System#nanoTime()} of its last
 * sign of life: every torque write, and every 5 ms from the board's watchdog thread while a torque is on) and
 * the armed flag (a non-zero torque is on the motors). The guard writes the guard-write counter (incremented
 * before each zero-torque write it makes to the board while the JVM is paused, so that the board can count the
 * replies those writes cause) and its state (whether it could open the port for writing).
 *
 * <p>The values are only compared for change, never across processes as times.
 *
 * <p>Not API: public only for {@link tactus.haptics.Board}.
 */
public final class GuardHeartbeat {
    /** Size of the shared file in bytes. */
    static final int SIZE = 64;
    static final long MAGIC = 0x7461637475734842L;   // "tactusHB"
    /** Guard state: not known yet. */
    static final long STATE_WAITING = 0;
    /** Guard state: the guard holds the port open for writing and watches the heartbeat. */
    static final long STATE_READY = 1;
    /** Guard state: the guard could not open the port for writing: it cannot zero the motors of a paused JVM. */
    static final long STATE_NO_PORT = -1;

    private static final int OFF_MAGIC = 0;
    private static final int OFF_BEAT = 8;
    private static final int OFF_ARMED = 16;
    private static final int OFF_GUARD_WRITES = 24;
    private static final int OFF_STATE = 32;
    private static final VarHandle LONGS = MethodHandles.byteBufferViewVarHandle(long[].class, ByteOrder.nativeOrder());

    /** A heartbeat that goes nowhere (no guard, or no shared memory): every call does nothing. */
    static final GuardHeartbeat NONE = new GuardHeartbeat(null, null);

    private final MappedByteBuffer buf;
    private final Path path;

    private GuardHeartbeat(MappedByteBuffer buf, Path path) {
        this.buf = buf;
        this.path = path;
    }

    /**
     * Creates a new shared file (in /dev/shm where it exists, so that no page is ever written back to a disk,
     * else in java.io.tmpdir) and maps it; for the sketch's JVM.
     */
    static GuardHeartbeat create() throws IOException {
        Path shm = Paths.get("/dev/shm");
        Path dir = Files.isDirectory(shm) && Files.isWritable(shm) ? shm : Paths.get(System.getProperty("java.io.tmpdir"));
        Path p = Files.createTempFile(dir, "tactus-guard-", ".hb");
        try {
            GuardHeartbeat h = map(p, true);
            LONGS.setRelease(h.buf, OFF_MAGIC, MAGIC);
            return h;
        } catch (IOException | RuntimeException e) {
            Files.deleteIfExists(p);
            throw e;
        }
    }

    /** Maps an existing shared file made by {@link #create()}; for the guard. */
    static GuardHeartbeat open(String path) throws IOException {
        GuardHeartbeat h = map(Paths.get(path), false);
        if ((long) LONGS.getAcquire(h.buf, OFF_MAGIC) != MAGIC) {
            throw new IOException(path + " is not a tactus heartbeat file");
        }
        return h;
    }

    private static GuardHeartbeat map(Path p, boolean sizeIt) throws IOException {
        try (FileChannel ch = FileChannel.open(p, StandardOpenOption.READ, StandardOpenOption.WRITE)) {
            if (sizeIt) {
                ch.write(java.nio.ByteBuffer.allocate(SIZE), 0);
            } else if (ch.size() < SIZE) {
                throw new IOException(p + " is too short");
            }
            MappedByteBuffer b = ch.map(FileChannel.MapMode.READ_WRITE, 0, SIZE);
            return new GuardHeartbeat(b, p);
        }
    }

    /** True unless this is {@link #NONE}. */
    public boolean isShared() {
        return buf != null;
    }

    /** The path of the shared file. */
    String path() {
        return path.toString();
    }

    /** Removes the file's name (both sides keep their mapping); for the sketch's JVM, once the guard has it. */
    void unlink() {
        if (path != null) {
            try {
                Files.deleteIfExists(path);
            } catch (IOException ignored) {
                // a stale 64-byte file in a temporary directory
            }
        }
    }

    // ---------------------------------------------------------------------------- the sketch's JVM writes

    /** A sign of life: stores the time now (ns) as the heartbeat. One memory store, no system call. */
    public void beat(long nanos) {
        if (buf != null) {
            LONGS.setOpaque(buf, OFF_BEAT, nanos);
        }
    }

    /** Says whether a non-zero torque is on the motors (only then does the guard watch the heartbeat). */
    public void arm(boolean on) {
        if (buf != null) {
            LONGS.setOpaque(buf, OFF_ARMED, on ? 1L : 0L);
        }
    }

    /** The number of zero-torque writes the guard has made (or is about to make) to the board. */
    public long guardWrites() {
        return buf == null ? 0 : (long) LONGS.getAcquire(buf, OFF_GUARD_WRITES);
    }

    /** The guard's state: {@link #STATE_WAITING}, {@link #STATE_READY} or {@link #STATE_NO_PORT}. */
    long state() {
        return buf == null ? STATE_NO_PORT : (long) LONGS.getAcquire(buf, OFF_STATE);
    }

    // ---------------------------------------------------------------------------- the guard writes

    /** The last heartbeat stored by the sketch's JVM. */
    long heartbeat() {
        return (long) LONGS.getOpaque(buf, OFF_BEAT);
    }

    /** True while the sketch's JVM says a non-zero torque is on. */
    boolean armed() {
        return (long) LONGS.getOpaque(buf, OFF_ARMED) != 0;
    }

    /** Counts one more guard write; called before the write itself, so the count is never behind the bytes. */
    void countGuardWrite() {
        // volatile: the count is visible before the write's bytes can be
        LONGS.setVolatile(buf, OFF_GUARD_WRITES, (long) LONGS.getOpaque(buf, OFF_GUARD_WRITES) + 1);
    }

    /** Sets the guard's state. */
    void setState(long state) {
        LONGS.setRelease(buf, OFF_STATE, state);
    }
}
