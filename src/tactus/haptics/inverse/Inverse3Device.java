package tactus.haptics.inverse;

import java.net.URI;

import tactus.haptics.HaplyLinkException;
import tactus.haptics.HapticDevice;
import tactus.haptics.WorkspaceMapping;

/**
 * An Inverse3 (or Inverse3x, or Minverse) through the Inverse Service, as a {@link HapticDevice}: each tick
 * takes the newest state frame the socket thread parsed (never waiting) and sends one {@code set_cursor_force},
 * which the service answers with the next frame. Positions are the service's {@code cursor_position} in metres,
 * velocities its {@code cursor_velocity}, forces newtons along the same axes. The VerseGrip's orientation and
 * buttons, when one is listed, are read with {@link #readState(InverseState)} from any thread.
 */
public final class Inverse3Device implements HapticDevice {
    private final InverseServiceClient client;
    private final InverseState state = new InverseState();   // the loop thread's copy
    private long lastFrame = -1;

    /** Wraps an open client. */
    public Inverse3Device(InverseServiceClient client) {
        if (client == null) {
            throw new IllegalArgumentException("Inverse3Device: client must not be null");
        }
        this.client = client;
        client.read(state);
    }

    /** Connects to the service at {@link InverseServiceClient#DEFAULT_URI} (2 s at most). */
    public static Inverse3Device open() {
        return new Inverse3Device(InverseServiceClient.connect());
    }

    /** Connects to the service at this address (e.g. {@code ws://localhost:10001}), waiting at most timeoutMillis. */
    public static Inverse3Device open(URI uri, long timeoutMillis) {
        return new Inverse3Device(InverseServiceClient.connect(uri, timeoutMillis));
    }

    /** The connection. */
    public InverseServiceClient client() {
        return client;
    }

    /** Copies the newest state (Inverse3 and VerseGrip) into out, from any thread; returns its frame number. */
    public long readState(InverseState out) {
        return client.read(out);
    }

    /** The device's kind as the service names it: "inverse3", "inverse3x" or "minverse". */
    public String kind() {
        return state.deviceType == null ? "inverse3" : state.deviceType;
    }

    @Override
    public int dimensions() {
        return 3;
    }

    @Override
    public boolean isReady() {
        return client.lostReason() == null && !client.isClosed();
    }

    @Override
    public void begin() {
        client.sendForce(0, 0, 0);   // the service answers with the first frame
    }

    @Override
    public boolean update() {
        String why = client.lostReason();
        if (why != null) {
            throw new HaplyLinkException(why);
        }
        long f = client.read(state);
        if (f == lastFrame) {
            return false;
        }
        lastFrame = f;
        if (state.inverse3Count == 0) {
            throw new HaplyLinkException("the Haply Inverse Service no longer lists the Inverse3 " + state.deviceId
                    + ": was it unplugged or switched off?");
        }
        return !Double.isNaN(state.px);
    }

    @Override
    public void position(double[] out) {
        out[0] = state.px;
        out[1] = state.py;
        out[2] = state.pz;
    }

    @Override
    public void velocity(double[] out) {
        out[0] = state.vx;
        out[1] = state.vy;
        out[2] = state.vz;
    }

    @Override
    public void sendForce(double fx, double fy, double fz) {
        if (!Double.isFinite(fx) || !Double.isFinite(fy) || !Double.isFinite(fz)) {
            client.sendForce(0, 0, 0);
        } else {
            client.sendForce(fx, fy, fz);
        }
    }

    @Override
    public void zeroForce() {
        client.zeroForce();
    }

    @Override
    public WorkspaceMapping defaultMapping() {
        return defaultMappingOfTheFamily();
    }

    /** The default mapping of the Inverse3 family ({@link WorkspaceMapping#inverse3YUp()}): model y up. */
    public static WorkspaceMapping defaultMappingOfTheFamily() {
        return WorkspaceMapping.inverse3YUp();
    }

    @Override
    public String describe() {
        return "Haply " + kind() + " " + state.deviceId + " through the Inverse Service at " + client.uri();
    }

    @Override
    public String status() {
        String why = client.lostReason();
        return why != null ? "lost: " + why : client.isClosed() ? "closed"
                : "open, " + client.messagesSent() + " sent, " + client.sendsSkipped() + " skipped";
    }

    @Override
    public void close() {
        client.close();
    }

    @Override
    public String toString() {
        return describe();
    }
}
