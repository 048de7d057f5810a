package tactus.haptics;

import com.fazecast.jSerialComm.SerialPort;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** Serial port discovery: lists the ports and picks the one that looks like a Haply board. */
public final class SerialPorts {
    /** USB vendor ids of the microcontrollers on Haply boards (Arduino, Atmel/Microchip, Adafruit, SparkFun). */
    private static final int[] HAPLY_VENDORS = {0x2341, 0x03EB, 0x239A, 0x1B4F, 0x2A03};

    private SerialPorts() {
    }

    /** The system names of every serial port, e.g. "/dev/ttyACM0" or "COM3" (like Processing's Serial.list()). */
    public static String[] list() {
        SerialPort[] ports = SerialPort.getCommPorts();
        String[] out = new String[ports.length];
        for (int i = 0; i < ports.length; i++) {
            out[i] = ports[i].getSystemPortPath();
        }
        return out;
    }

    /** One line per port: path, description and USB vendor id, or "none". */
    public static String describeAll() {
        SerialPort[] ports;
        try {
            ports = SerialPort.getCommPorts();
        } catch (Throwable t) {
            return "(cannot list ports: " + t + ")";
        }
        if (ports.length == 0) {
            return "none";
        }
        StringBuilder sb = new StringBuilder();
        for (SerialPort p : ports) {
            if (sb.length() > 0) {
                sb.append(", ");
            }
            sb.append(p.getSystemPortPath()).append(" (").append(p.getPortDescription());
            if (p.getVendorID() >= 0) {
                sb.append(String.format(Locale.ROOT, ", USB %04x:%04x", p.getVendorID(), p.getProductID()));
            }
            sb.append(')');
        }
        return sb.toString();
    }

    /**
     * True if a port with this path, description and USB vendor id looks like a Haply board: a known
     * microcontroller vendor, or a native-USB CDC name (ttyACM, cu.usbmodem) when the vendor is unknown.
     */
    public static boolean looksLikeHaply(String path, String description, int vendorId) {
        for (int v : HAPLY_VENDORS) {
            if (v == vendorId) {
                return true;
            }
        }
        String p = path == null ? "" : path.toLowerCase(Locale.ROOT);
        String d = description == null ? "" : description.toLowerCase(Locale.ROOT);
        if (d.contains("haply") || d.contains("arduino") || d.contains("samd") || d.contains("zero")) {
            return true;
        }
        return vendorId < 0 && (p.contains("ttyacm") || p.contains("usbmodem"));
    }

    /** The paths of the ports that look like Haply boards, best first. */
    public static List<String> candidates() {
        List<String> out = new ArrayList<>();
        for (SerialPort p : SerialPort.getCommPorts()) {
            if (looksLikeHaply(p.getSystemPortPath(), p.getPortDescription(), p.getVendorID())) {
                out.add(p.getSystemPortPath());
            }
        }
        return out;
    }

    /**
     * The path of the first port that looks like a Haply board. Throws {@link HaplyLinkException} saying what
     * to check if there is none.
     */
    public static String findHaply() {
        List<String> c = candidates();
        if (c.isEmpty()) {
            throw new HaplyLinkException("no Haply board found. Check that the board is plugged in with a data "
                    + "(not charge-only) USB cable and powered, that its firmware is running, and on Linux that "
                    + "you are in the 'dialout' group. Serial ports seen: " + describeAll()
                    + ". Pass the port name to new Board(...) if it is there under another name.");
        }
        return c.get(0);
    }
}
