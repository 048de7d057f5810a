package tactus.haptics.emulator;

import tactus.haptics.Board;
import tactus.haptics.HaplyLinkException;
import tactus.haptics.HaplyPreset;
import tactus.haptics.SerialPorts;

/**
 * A board for an example: the first Haply found, or else an emulated one whose hand follows a target (the
 * mouse). {@link #status()} says which, for the screen. Classrooms often have fewer devices than students.
 */
public final class HaplyConnection implements AutoCloseable {
    private final Board board;
    private final BoardEmulator emulator;
    private final Hand hand;
    private final String status;

    private HaplyConnection(Board board, BoardEmulator emulator, Hand hand, String status) {
        this.board = board;
        this.emulator = emulator;
        this.hand = hand;
        this.status = status;
    }

    /**
     * Opens the first serial port that looks like a Haply board; if there is none, or it cannot be opened,
     * an in-process emulator of the preset's hardware whose hand follows {@link #setHandTarget}.
     */
    public static HaplyConnection open(HaplyPreset preset) {
        if (preset == null) {
            throw new IllegalArgumentException("HaplyConnection.open: preset must not be null");
        }
        String why;
        try {
            String port = SerialPorts.findHaply();
            Board b = new Board(port, 0);
            return new HaplyConnection(b, null, null, "Haply board on " + port);
        } catch (HaplyLinkException | UnsatisfiedLinkError | NoClassDefFoundError e) {
            why = e.getMessage();
        }
        return emulated(preset, emulatedStatus(firstSentence(why)));
    }

    /** An in-process emulator of the preset's hardware whose hand follows {@link #setHandTarget}. */
    public static HaplyConnection emulated(HaplyPreset preset, String status) {
        BoardEmulator emu = new BoardEmulator(preset);
        Hand h = Hand.following(emu.x(), emu.y(), 300, 3);
        emu.setHand(h);
        return new HaplyConnection(new Board(emu.connect()), emu, h, status);
    }

    /**
     * The status line of the fallback: "no Haply board found: ..." when that is the whole reason (the message of
     * {@link SerialPorts#findHaply()} says just that in its first sentence), with the reason in brackets otherwise
     * (a port that could not be opened, a missing serial library).
     */
    static String emulatedStatus(String reason) {
        String tail = ": emulated board, the mouse is the hand";
        if (reason == null || reason.isEmpty() || reason.trim().equalsIgnoreCase("no Haply board found")) {
            return "no Haply board found" + tail;
        }
        return "no Haply board found (" + reason + ")" + tail;
    }

    private static String firstSentence(String s) {
        if (s == null) {
            return "unknown reason";
        }
        int dot = s.indexOf(". ");
        return dot > 0 ? s.substring(0, dot) : s;
    }

    /** The board (real or emulated). */
    public Board board() {
        return board;
    }

    /** True if the board is emulated. */
    public boolean isEmulated() {
        return emulator != null;
    }

    /** The emulator, or null on real hardware. */
    public BoardEmulator emulator() {
        return emulator;
    }

    /** One line for the screen: which board, and whether the mouse is the hand. */
    public String status() {
        return status;
    }

    /** Moves the emulated hand's target to (x, y) in metres (device coordinates); does nothing on real hardware. */
    public void setHandTarget(double x, double y) {
        if (hand != null) {
            hand.setTarget(x, y);
        }
    }

    /** Closes the board (zero torques first). */
    @Override
    public void close() {
        board.close();
        if (emulator != null) {
            emulator.close();
        }
    }
}
