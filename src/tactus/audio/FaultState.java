package tactus.audio;

/**
 * The fault state of one {@link PhyUGen}: written by its audio thread when something it reads or steps fails or
 * comes back, read by any thread ({@link PhyUGen#isSilenced()}, {@link PhyUGen#getLastError()}). Each change posts
 * one {@link FaultNotice} to the {@link FaultReporter}, never one per sample; after {@link #MAX_NOTICES} notices a
 * PhyUGen stays quiet (its state is still kept).
 */
final class FaultState {
    /** Notices one PhyUGen may print; a model that keeps failing and recovering says so this many times at most. */
    static final int MAX_NOTICES = 32;

    private final PhyUGen source;
    private volatile Throwable lastError;
    private volatile boolean silenced;
    private volatile boolean avatarLost;
    private volatile long faults;
    private int notices;
    private boolean unexpectedReported;

    FaultState(PhyUGen source) {
        this.source = source;
    }

    /** @return true while the whole output is silent: the model cannot step (diverged, or its steps throw). */
    boolean isSilenced() {
        return silenced;
    }

    /** @return true while the attached avatar cannot be driven (it left the model). */
    boolean isAvatarLost() {
        return avatarLost;
    }

    /** @return the last error met on the audio thread, or null; kept after recovery. */
    Throwable lastError() {
        return lastError;
    }

    /** @return how many faults the audio thread met (model silenced, point or avatar lost, own failure). */
    long faultCount() {
        return faults;
    }

    // ---------------------------------------------------------------- the audio thread

    /** The model stopped stepping: diverged (error null if a listener was told), a listener threw, or a step threw. */
    void modelSilenced(FaultNotice.Kind kind, Throwable error) {
        silenced = true;
        fault(error);
        post(kind, null, error);
    }

    void modelSoundsAgain() {
        silenced = false;
        post(FaultNotice.Kind.SOUNDS_AGAIN, null, null);
    }

    void pointLost(ListeningPoint p, Throwable error) {
        fault(error);
        post(FaultNotice.Kind.POINT_LOST, p, error);
    }

    void pointBack(ListeningPoint p) {
        post(FaultNotice.Kind.POINT_BACK, p, null);
    }

    void avatarLost(String name, Throwable error) {
        avatarLost = true;
        fault(error);
        post(FaultNotice.Kind.AVATAR_LOST, name, error);
    }

    void avatarBack(String name) {
        avatarLost = false;
        post(FaultNotice.Kind.AVATAR_BACK, name, null);
    }

    /** Clears the avatar state when the avatar is attached or detached (any thread, under the PhyUGen's monitor). */
    void avatarReset() {
        avatarLost = false;
    }

    /** The PhyUGen's own code threw: reported the first time only (it may throw every sample). */
    void unexpected(Throwable error) {
        fault(error);
        if (!unexpectedReported) {
            unexpectedReported = true;
            post(FaultNotice.Kind.UNEXPECTED, null, error);
        }
    }

    private void fault(Throwable error) {
        faults++;
        if (error != null) {
            lastError = error;
        }
    }

    private void post(FaultNotice.Kind kind, Object subject, Throwable error) {
        if (notices < MAX_NOTICES) {
            FaultReporter.post(new FaultNotice(kind, source, subject, error));
        } else if (notices == MAX_NOTICES) {
            FaultReporter.post(new FaultNotice(FaultNotice.Kind.SUPPRESSED, source, MAX_NOTICES, null));
        }
        if (notices <= MAX_NOTICES) {
            notices++;
        }
    }
}
