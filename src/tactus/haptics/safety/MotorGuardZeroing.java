package tactus.haptics.safety;

import com.fazecast.jSerialComm.SerialPort;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Arrays;
import java.util.Map;
import java.util.concurrent.locks.LockSupport;
import tactus.haptics.transport.WireFormat;

/**
 * What the {@link MotorGuard} does once its parent is gone: opens the port, sends every device a write with
 * zero torques and zero PWM (the firmware keeps the last duty until then), waits for the replies, sends a
 * reset and closes the port. Every wait is bounded.
 */
final class MotorGuardZeroing {
    /** How long to retry opening the port (the dead parent's lock may take a moment to go), in ms. */
    static final long OPEN_RETRY_MS = 1_000;
    /** How long to wait for the replies to the zero writes, in ms. */
    static final long REPLY_WAIT_MS = 250;

    private MotorGuardZeroing() {
    }

    /**
     * The identity of a port's device node (on Unix its change time and device number: a freed and reused
     * pseudo-terminal, or a board plugged in again, gets a new one), or null where it cannot be read.
     */
    static Object identity(String portName) {
        try {
            Path p = Paths.get(portName);
            return Arrays.asList(Files.getAttribute(p, "unix:ctime"), Files.getAttribute(p, "unix:rdev"));
        } catch (Exception e) {
            return null;
        }
    }

    /**
     * Sends zero torques to the devices ({id: {writeBytes, replyBytes}}) on a port, then a reset. Returns one
     * line saying what was done, for the console.
     */
    static String zero(String portName, int baud, Object identity, Map<Integer, int[]> devices) {
        long start = System.nanoTime();
        if (identity != null && !identity.equals(identity(portName))) {
            return portName + " is no longer the port the sketch had (replaced or gone): nothing sent";
        }
        SerialPort port = open(portName, baud);
        if (port == null) {
            return "could not open " + portName + " within " + OPEN_RETRY_MS + " ms: nothing sent";
        }
        try {
            int stale = port.bytesAvailable();
            if (stale > 0) {
                port.readBytes(new byte[stale], stale);
            }
            int owed = 0;
            StringBuilder ids = new StringBuilder();
            for (Map.Entry<Integer, int[]> d : devices.entrySet()) {
                byte[] zeros = zeroMessage(d.getKey(), d.getValue()[0]);
                if (port.writeBytes(zeros, zeros.length) != zeros.length) {
                    return "the write of zero torques to " + portName + " failed (error " + port.getLastErrorCode() + ")";
                }
                owed += d.getValue()[1];
                ids.append(ids.length() == 0 ? "" : ", ").append(d.getKey());
            }
            long deadline = System.nanoTime() + REPLY_WAIT_MS * 1_000_000L;
            int got = port.bytesAvailable();
            while (got >= 0 && got < owed && System.nanoTime() - deadline < 0) {
                LockSupport.parkNanos(500_000);
                got = port.bytesAvailable();
            }
            port.writeBytes(WireFormat.reset((byte) 0), 2);
            LockSupport.parkNanos(20_000_000);   // let the reset leave before the port closes
            long ms = (System.nanoTime() - start) / 1_000_000;
            return "sent zero torques to device " + ids + " on " + portName + (got >= owed
                    ? " (answered" : " (no answer within " + REPLY_WAIT_MS + " ms") + ", " + ms + " ms)";
        } finally {
            port.closePort();
        }
    }

    /** A device's write with zero torques and zero PWM: [2][id], then PWM bytes and float32 torques, all 0. */
    static byte[] zeroMessage(int id, int length) {
        byte[] zeros = new byte[length];
        zeros[0] = WireFormat.WRITE;
        zeros[1] = (byte) id;
        return zeros;
    }

    private static SerialPort open(String portName, int baud) {
        long deadline = System.nanoTime() + OPEN_RETRY_MS * 1_000_000L;
        while (true) {
            try {
                SerialPort port = SerialPort.getCommPort(portName);
                port.setComPortParameters(baud, 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
                port.setFlowControl(SerialPort.FLOW_CONTROL_DISABLED);
                port.setComPortTimeouts(SerialPort.TIMEOUT_NONBLOCKING, 0, 0);
                if (port.openPort(0)) {
                    return port;
                }
            } catch (RuntimeException e) {
                // not there (yet): retry until the deadline
            }
            if (System.nanoTime() - deadline > 0) {
                return null;
            }
            LockSupport.parkNanos(20_000_000);
        }
    }
}
