package tactus.internal.snapshot;

import java.util.concurrent.atomic.AtomicInteger;

/**
 * A lock-free triple buffer of {@link SnapshotBuffer}s between the one thread that steps the model (the writer,
 * holding the model's lock) and the one thread that draws it (the reader, holding no lock). The writer fills its
 * back buffer and swaps it with the middle one; the reader swaps the middle one with its front buffer when a newer
 * copy is there. Neither ever waits for the other, no copy is ever torn, and nothing is allocated once the
 * buffers have the model's size.
 */
public final class SnapshotExchange {
    private static final int FRESH = 4;
    private final SnapshotBuffer[] buffers = {new SnapshotBuffer(this), new SnapshotBuffer(this), new SnapshotBuffer(this)};
    /** Set by the reader ({@code ModelSnapshot.requestMotion}): copy every mass's velocity and force too. */
    public volatile boolean motion;
    /** Set by the reader ({@code ModelSnapshot.requestLinks}): copy the interactions too (the default). */
    public volatile boolean links = true;
    /** Index of the middle buffer, plus FRESH when the writer has published into it since the reader last took it. */
    private final AtomicInteger middle = new AtomicInteger(1);
    private int back = 0;
    private int front = 2;

    /** @return the writer's buffer, to fill before {@link #publish()}. */
    public SnapshotBuffer back() {
        return buffers[back];
    }

    /** Hands the filled back buffer to the reader. Called by the writer only. */
    public void publish() {
        back = middle.getAndSet(back | FRESH) & 3;
    }

    /** @return the newest published copy; it stays the reader's until its next call. Called by the reader only. */
    public SnapshotBuffer latest() {
        if ((middle.get() & FRESH) != 0) {
            front = middle.getAndSet(front) & 3;
        }
        return buffers[front];
    }
}
