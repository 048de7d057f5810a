package tactus.haptics.transport;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The V2 wire format, byte for byte. */
class WireFormatTest {
    private static byte[] bytes(int... v) {
        byte[] b = new byte[v.length];
        for (int i = 0; i < v.length; i++) {
            b[i] = (byte) v[i];
        }
        return b;
    }

    @Test
    void floatsAreLittleEndianBinary32() {
        byte[] b = new byte[4];
        WireFormat.putFloat(b, 0, 1.0f);           // 0x3F800000
        assertArrayEquals(bytes(0x00, 0x00, 0x80, 0x3F), b);
        WireFormat.putFloat(b, 0, -2.5f);          // 0xC0200000
        assertArrayEquals(bytes(0x00, 0x00, 0x20, 0xC0), b);
        WireFormat.putFloat(b, 0, 13824f);         // 0x46580000
        assertArrayEquals(bytes(0x00, 0x00, 0x58, 0x46), b);
        for (float f : new float[] {0f, -0f, 0.123f, 167.90164f, Float.MIN_VALUE, -1e30f}) {
            WireFormat.putFloat(b, 0, f);
            assertEquals(Float.floatToRawIntBits(f), Float.floatToRawIntBits(WireFormat.getFloat(b, 0)));
        }
    }

    @Test
    void setupOfHelloWallIs26Bytes() {
        // two motors CW on ports 1-2, encoders (CW, 180, 13824, port 1), (CW, 0, 13824, port 2), id 3
        byte[] m = WireFormat.setup((byte) 3, new int[] {0, 0}, new int[] {0, 0},
                new float[] {180f, 0f}, new float[] {13824f, 13824f}, new int[0], new int[0]);
        byte[] expected = bytes(0x01, 0x03, 0x03, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00, 0x00,
                0x00, 0x00, 0x34, 0x43, 0x00, 0x00, 0x58, 0x46,   // 180f = 0x43340000, 13824f
                0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x58, 0x46);  // 0f, 13824f
        assertArrayEquals(expected, m);
    }

    @Test
    void setupPutsDirectionsAndParametersInPortOrder() {
        // 2DIY v3: encoder 1 (CCW, 168) on port 2, encoder 2 (CCW, 12) on port 1; one analog A1; PWM pins 4, 13
        byte[] m = WireFormat.setup((byte) 5, new int[] {1, 0}, new int[] {1, 1},
                new float[] {12f, 168f}, new float[] {4880f, 4880f}, new int[] {55}, new int[] {4, 13});
        assertEquals(0x01, m[0]);
        assertEquals(5, m[1]);
        assertEquals(0x03, m[2]);
        assertEquals(1, m[3]);
        assertEquals(0, m[4]);
        assertEquals(0x03, m[5]);
        assertEquals(1, m[6]);
        assertEquals(1, m[7]);
        assertEquals(1, m[8]);
        assertEquals(55, m[9]);
        assertEquals(2, m[10]);
        assertEquals(4, m[11]);
        assertEquals(13, m[12]);
        assertEquals(12f, WireFormat.getFloat(m, 13));   // port 1 first
        assertEquals(4880f, WireFormat.getFloat(m, 17));
        assertEquals(168f, WireFormat.getFloat(m, 21));
        assertEquals(4880f, WireFormat.getFloat(m, 25));
        assertEquals(29, m.length);
    }

    @Test
    void writeIsCodeIdPwmThenTorques() {
        byte[] out = new byte[WireFormat.writeLength(1, 2)];
        int n = WireFormat.encodeWrite((byte) 3, new int[] {200}, 1, new float[] {1.0f, -2.5f}, 2, out);
        assertEquals(11, n);
        assertArrayEquals(bytes(0x02, 0x03, 200, 0x00, 0x00, 0x80, 0x3F, 0x00, 0x00, 0x20, 0xC0), out);
        assertEquals(9, WireFormat.replyLength(2));
        assertArrayEquals(bytes(0x00, 0x07), WireFormat.reset((byte) 7));
    }
}
