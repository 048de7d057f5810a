package tactus.haptics.emulator;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Base64;
import java.util.Locale;

/**
 * The server side of one WebSocket connection (RFC 6455) over a plain socket, just what the Inverse Service
 * emulator needs: the HTTP upgrade, text messages (fragmented or not) in and out, ping answered with pong,
 * and the closing handshake. Client frames must be masked (section 5.1); server frames are not. Binary messages
 * are read and dropped. Not thread-safe: one thread reads and writes.
 */
final class WebSocketServerConnection implements AutoCloseable {
    private static final String GUID = "258EAFA5-E914-47DA-95CA-C5AB0DC85B11";
    /** Largest message accepted, in bytes (the service's commands are a few hundred bytes). */
    static final int MAX_MESSAGE = 1 << 20;

    private final Socket socket;
    private final InputStream in;
    private final OutputStream out;
    private final ByteArrayOutputStream message = new ByteArrayOutputStream(1024);
    private String path = "/";
    private boolean closeSent;

    WebSocketServerConnection(Socket socket) throws IOException {
        this.socket = socket;
        socket.setTcpNoDelay(true);
        this.in = new BufferedInputStream(socket.getInputStream(), 8192);
        this.out = new BufferedOutputStream(socket.getOutputStream(), 8192);
    }

    /** What answers a plain HTTP request on the WebSocket's port. */
    interface HttpRoutes {
        /**
         * Answers one request: returns {status code and reason (e.g. "200 OK"), JSON body}; method is "GET",
         * "POST", ..., target the request target (path and query).
         */
        String[] answer(String method, String target);
    }

    /** Reads the HTTP request and answers it; see {@link #handshake(HttpRoutes)} (every plain request gets a 404). */
    boolean handshake() throws IOException {
        return handshake(null);
    }

    /**
     * Reads the HTTP request and answers it: 101 with the accept key for a WebSocket upgrade (returns true), or,
     * for a plain HTTP request, what the routes answer (a 404 without routes) with the connection closed
     * afterwards (returns false; the caller closes).
     */
    boolean handshake(HttpRoutes routes) throws IOException {
        String requestLine = line();
        String key = null;
        boolean upgrade = false;
        int contentLength = 0;
        for (String h = line(); !h.isEmpty(); h = line()) {
            int colon = h.indexOf(':');
            if (colon < 0) {
                continue;
            }
            String name = h.substring(0, colon).trim().toLowerCase(Locale.ROOT);
            String value = h.substring(colon + 1).trim();
            if (name.equals("sec-websocket-key")) {
                key = value;
            } else if (name.equals("upgrade") && value.toLowerCase(Locale.ROOT).contains("websocket")) {
                upgrade = true;
            } else if (name.equals("content-length")) {
                try {
                    contentLength = Integer.parseInt(value);
                } catch (NumberFormatException e) {
                    contentLength = 0;
                }
            }
        }
        String[] parts = requestLine.split(" ");
        if (parts.length >= 2) {
            path = parts[1];
        }
        if (!upgrade || key == null || !requestLine.startsWith("GET ")) {
            for (int i = 0; i < contentLength && i < MAX_MESSAGE && in.read() >= 0; i++) {
                // a request body is read and dropped: no route takes one
            }
            String[] answer = routes != null && parts.length >= 2 ? routes.answer(parts[0], parts[1])
                    : new String[] {"404 Not Found", "{\"ok\":false,\"error\":\"the Tactus Inverse Service emulator "
                    + "speaks WebSocket only\"}"};
            byte[] body = answer[1].getBytes(StandardCharsets.UTF_8);
            writeAscii("HTTP/1.1 " + answer[0] + "\r\nContent-Type: application/json\r\nContent-Length: " + body.length
                    + "\r\nConnection: close\r\n\r\n");
            out.write(body);
            out.flush();
            return false;
        }
        writeAscii("HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Accept: "
                + accept(key) + "\r\n\r\n");
        out.flush();
        return true;
    }

    /** The request path of the upgrade (e.g. "/"). */
    String path() {
        return path;
    }

    /** The Sec-WebSocket-Accept value for a client's key. */
    static String accept(String key) {
        try {
            MessageDigest sha1 = MessageDigest.getInstance("SHA-1");
            byte[] digest = sha1.digest((key + GUID).getBytes(StandardCharsets.US_ASCII));
            return Base64.getEncoder().encodeToString(digest);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-1 is missing from this JVM", e);
        }
    }

    /**
     * Reads the next text message; answers pings and skips pongs and binary messages on the way. Returns null
     * when the client closes (the close is answered) or the socket ends.
     */
    String readText() throws IOException {
        message.reset();
        int messageOpcode = -1;
        while (true) {
            int b0 = in.read();
            if (b0 < 0) {
                return null;
            }
            int b1 = readByte();
            boolean fin = (b0 & 0x80) != 0;
            int opcode = b0 & 0x0F;
            boolean masked = (b1 & 0x80) != 0;
            long len = b1 & 0x7F;
            if (len == 126) {
                len = (readByte() << 8) | readByte();
            } else if (len == 127) {
                len = 0;
                for (int i = 0; i < 8; i++) {
                    len = (len << 8) | readByte();
                }
            }
            if (!masked) {
                close(1002, "client frames must be masked");
                return null;
            }
            if (len > MAX_MESSAGE || message.size() + len > MAX_MESSAGE) {
                close(1009, "message too big");
                return null;
            }
            byte[] mask = new byte[4];
            readFully(mask);
            byte[] payload = new byte[(int) len];
            readFully(payload);
            for (int i = 0; i < payload.length; i++) {
                payload[i] ^= mask[i & 3];
            }
            if (opcode == 0x8) {
                if (!closeSent) {
                    int code = payload.length >= 2 ? ((payload[0] & 0xFF) << 8) | (payload[1] & 0xFF) : 1000;
                    close(code == 1005 || code == 1006 ? 1000 : code, "");
                }
                return null;
            } else if (opcode == 0x9) {
                writeFrame(0xA, payload);
                continue;
            } else if (opcode == 0xA) {
                continue;
            }
            if (opcode != 0x0) {
                messageOpcode = opcode;
            }
            message.write(payload, 0, payload.length);
            if (fin) {
                if (messageOpcode == 0x1) {
                    return new String(message.toByteArray(), StandardCharsets.UTF_8);
                }
                message.reset();   // a binary message: dropped
                messageOpcode = -1;
            }
        }
    }

    /** Sends one text message in one frame. */
    void sendText(String text) throws IOException {
        writeFrame(0x1, text.getBytes(StandardCharsets.UTF_8));
    }

    /** Sends a close frame with this code and reason (once), and closes the socket. */
    void close(int code, String reason) {
        try {
            if (!closeSent) {
                closeSent = true;
                byte[] r = reason.getBytes(StandardCharsets.UTF_8);
                byte[] p = new byte[2 + r.length];
                p[0] = (byte) (code >> 8);
                p[1] = (byte) code;
                System.arraycopy(r, 0, p, 2, r.length);
                writeFrame(0x8, p);
            }
        } catch (IOException e) {
            // the socket is gone already
        } finally {
            close();
        }
    }

    /** Closes the socket at once, without a closing handshake (as a crashed service would). */
    @Override
    public void close() {
        try {
            socket.close();
        } catch (IOException e) {
            // nothing to do
        }
    }

    private void writeFrame(int opcode, byte[] payload) throws IOException {
        out.write(0x80 | opcode);
        int n = payload.length;
        if (n < 126) {
            out.write(n);
        } else if (n < 65536) {
            out.write(126);
            out.write(n >> 8);
            out.write(n);
        } else {
            out.write(127);
            for (int i = 7; i >= 0; i--) {
                out.write((int) ((long) n >> (8 * i)));
            }
        }
        out.write(payload);
        out.flush();
    }

    private void writeAscii(String s) throws IOException {
        out.write(s.getBytes(StandardCharsets.US_ASCII));
    }

    private String line() throws IOException {
        StringBuilder b = new StringBuilder();
        while (true) {
            int c = in.read();
            if (c < 0) {
                throw new EOFException("the connection ended inside the HTTP request");
            }
            if (c == '\n') {
                int n = b.length();
                if (n > 0 && b.charAt(n - 1) == '\r') {
                    b.setLength(n - 1);
                }
                return b.toString();
            }
            if (b.length() > 8192) {
                throw new IOException("HTTP header line too long");
            }
            b.append((char) c);
        }
    }

    private int readByte() throws IOException {
        int b = in.read();
        if (b < 0) {
            throw new EOFException("the connection ended inside a frame");
        }
        return b;
    }

    private void readFully(byte[] buf) throws IOException {
        int off = 0;
        while (off < buf.length) {
            int n = in.read(buf, off, buf.length - off);
            if (n < 0) {
                throw new EOFException("the connection ended inside a frame");
            }
            off += n;
        }
    }
}
