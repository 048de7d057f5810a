package tactus.haptics;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import tactus.haptics.transport.Transport;

/** Wraps a transport and records every write as one entry, so tests can see how commands went out. */
final class RecordingTransport implements Transport {
    final Transport inner;
    final List<byte[]> writes = new ArrayList<>();

    RecordingTransport(Transport inner) {
        this.inner = inner;
    }

    @Override
    public synchronized void write(byte[] data, int offset, int length) throws IOException {
        writes.add(java.util.Arrays.copyOfRange(data, offset, offset + length));
        inner.write(data, offset, length);
    }

    @Override
    public int available() throws IOException {
        return inner.available();
    }

    @Override
    public int read(byte[] buffer, int offset, int length) throws IOException {
        return inner.read(buffer, offset, length);
    }

    @Override
    public void close() {
        inner.close();
    }

    @Override
    public String describe() {
        return "recording " + inner.describe();
    }

    synchronized byte[] last() {
        return writes.get(writes.size() - 1);
    }
}
