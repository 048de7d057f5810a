/**
 * The byte links to a Haply board: the {@link tactus.haptics.transport.Transport} interface (reads never block,
 * writes are bounded), the serial port over jSerialComm ({@link tactus.haptics.transport.SerialTransport}) and the V2 wire
 * protocol's messages and float encoding ({@link tactus.haptics.transport.WireFormat}). A sketch rarely names them: a {@link tactus.haptics.Board} opens
 * its port by name ({@link tactus.haptics.SerialPorts}, which lists them, stays beside the hAPI classes as the
 * drop-in for Processing's {@code Serial.list()}), and the board emulator hands a board a transport of its own.
 */
package tactus.haptics.transport;
