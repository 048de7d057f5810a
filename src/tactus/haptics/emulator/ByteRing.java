package tactus.haptics.emulator;

/** A growable FIFO of bytes, synchronized. */
final class ByteRing {
    private byte[] buf = new byte[256];
    private int head;
    private int size;

    /** Takes up to len bytes; when there are none, waits for some up to timeoutNanos first. */
    synchronized int takeWaiting(byte[] out, int off, int len, long timeoutNanos) throws InterruptedException {
        long deadline = System.nanoTime() + timeoutNanos;
        while (size == 0) {
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                return 0;
            }
            wait(left / 1_000_000L, (int) (left % 1_000_000L));
        }
        return take(out, off, len);
    }

    synchronized void put(byte[] data, int off, int len) {
        if (size + len > buf.length) {
            byte[] nb = new byte[Math.max(buf.length * 2, size + len)];
            for (int i = 0; i < size; i++) {
                nb[i] = buf[(head + i) % buf.length];
            }
            buf = nb;
            head = 0;
        }
        for (int i = 0; i < len; i++) {
            buf[(head + size + i) % buf.length] = data[off + i];
        }
        size += len;
        notifyAll();
    }

    synchronized int size() {
        return size;
    }

    /** Removes and returns one byte (0..255), or -1 if empty. */
    synchronized int take() {
        if (size == 0) {
            return -1;
        }
        int b = buf[head] & 0xFF;
        head = (head + 1) % buf.length;
        size--;
        return b;
    }

    synchronized int take(byte[] out, int off, int len) {
        int n = Math.min(len, size);
        for (int i = 0; i < n; i++) {
            out[off + i] = buf[(head + i) % buf.length];
        }
        head = (head + n) % buf.length;
        size -= n;
        return n;
    }

    synchronized void clear() {
        head = 0;
        size = 0;
    }
}
