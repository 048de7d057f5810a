package tactus.haptics.emulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.SerialPorts;

/** With no Haply plugged in, an example gets the emulator with a hand that follows the mouse, and is told so. */
class HaplyConnectionTest {

    @Test
    void fallsBackToTheEmulatorAndTheHandFollowsTheTarget() {
        Assumptions.assumeTrue(SerialPorts.candidates().isEmpty(), "a Haply-like port is present");
        try (HaplyConnection c = HaplyConnection.open(HaplyPreset.TWO_DIY_V3)) {
            assertTrue(c.isEmulated());
            assertTrue(c.status().contains("no Haply board found") && c.status().contains("mouse"), c.status());
            assertFalse(c.status().contains("(no Haply board found"), "the reason said twice: " + c.status());
            Device d = new Device((byte) 5, c.board());
            HaplyPreset.TWO_DIY_V3.configure(d);
            d.device_set_parameters();
            c.emulator().setLockstep(0.001);
            c.setHandTarget(0.02, 0.10);
            for (int i = 0; i < 2000; i++) {     // 2 s of emulated time: the spring hand settles
                d.device_read_request();
                d.device_read_data();
            }
            float[] p = d.get_device_position(d.get_device_angles());
            assertEquals(0.02, p[0], 1e-3);
            assertEquals(0.10, p[1], 1e-3);
        }
    }

    @Test
    void noHaplySaysWhatToCheck() {
        Assumptions.assumeTrue(SerialPorts.candidates().isEmpty(), "a Haply-like port is present");
        tactus.haptics.HaplyLinkException e = org.junit.jupiter.api.Assertions.assertThrows(
                tactus.haptics.HaplyLinkException.class, SerialPorts::findHaply);
        assertTrue(e.getMessage().contains("USB cable") && e.getMessage().contains("dialout"), e.getMessage());
    }

    @Test
    void portDiscoveryRecognisesHaplyLikePorts() {
        assertTrue(SerialPorts.looksLikeHaply("/dev/ttyACM0", "Arduino Zero", 0x2341));
        assertTrue(SerialPorts.looksLikeHaply("COM7", "USB Serial Device", 0x03EB));
        assertTrue(SerialPorts.looksLikeHaply("/dev/cu.usbmodem1411", "", -1));
        assertTrue(!SerialPorts.looksLikeHaply("/dev/ttyS0", "Physical Port S0", -1));
        assertTrue(!SerialPorts.looksLikeHaply("/dev/ttyUSB0", "FT232R USB UART", 0x0403));
    }

    @Test
    void theFallbackStatusSaysTheReasonOnce() {
        assertEquals("no Haply board found: emulated board, the mouse is the hand",
                HaplyConnection.emulatedStatus("no Haply board found"));
        assertEquals("no Haply board found (port busy): emulated board, the mouse is the hand",
                HaplyConnection.emulatedStatus("port busy"));
        assertEquals("no Haply board found: emulated board, the mouse is the hand", HaplyConnection.emulatedStatus(null));
    }
}
