package tactus.audio;

/**
 * One thing a {@link PhyUGen}'s audio thread has to tell the user (a fault, or the recovery from one), built on the
 * audio thread from what it has at hand and turned into text by the {@link FaultReporter}'s thread, so that the
 * audio thread formats and prints nothing.
 */
final class FaultNotice {
    /** What happened. */
    enum Kind {
        /** The model diverged and is frozen; the output is silent. */
        DIVERGED,
        /** The model diverged and its DivergenceListener threw on the audio thread. */
        LISTENER_THREW,
        /** A step threw something else; the output is silent and stepping is retried. */
        STEP_FAILED,
        /** The model steps again after one of the three above. */
        SOUNDS_AGAIN,
        /** A listening point's element left the model. */
        POINT_LOST,
        /** A silent listening point's element is back. */
        POINT_BACK,
        /** The attached avatar left the model. */
        AVATAR_LOST,
        /** The attached avatar is back. */
        AVATAR_BACK,
        /** The PhyUGen's own code threw (a bug). */
        UNEXPECTED,
        /** Too many notices from one PhyUGen: the next ones are not printed. */
        SUPPRESSED
    }

    /** Retries of a failing step, per second at 44.1 kHz (see PhyUGen.RECHECK_SAMPLES). */
    private static final String RETRY_RATE = "about 20 times a second";

    final Kind kind;
    final PhyUGen source;
    final Object subject;
    final Throwable error;

    FaultNotice(Kind kind, PhyUGen source, Object subject, Throwable error) {
        this.kind = kind;
        this.source = source;
        this.subject = subject;
        this.error = error;
    }

    /** @return true when the stack trace of {@link #error} helps (a bug in a listener, the model or the PhyUGen). */
    boolean wantsStackTrace() {
        return error != null && (kind == Kind.LISTENER_THREW || kind == Kind.STEP_FAILED || kind == Kind.UNEXPECTED);
    }

    /** @return the text to print, starting "Tactus audio: ". */
    String message() {
        String u = name(source);
        String why = error == null ? null : error.getMessage() != null ? error.getMessage() : error.toString();
        switch (kind) {
            case DIVERGED:
                return "Tactus audio: " + u + " is silent: " + (why != null ? why : "the model diverged (its "
                        + "DivergenceListener was told)") + ". Its samples are written as 0 while the model is "
                        + "frozen; fix the model (positions, parameters) and call clearDivergence() on it to hear it again.";
            case LISTENER_THREW:
                return "Tactus audio: " + u + " is silent: the model diverged and its DivergenceListener threw " + error
                        + " on the audio thread (a listener must not throw; stack trace below). The model is frozen; fix "
                        + "it and call clearDivergence() on it to hear it again.";
            case STEP_FAILED:
                return "Tactus audio: " + u + " is silent: stepping the model threw " + error + " (stack trace below). "
                        + "It tries again " + RETRY_RATE + " and sounds again once a step succeeds.";
            case SOUNDS_AGAIN:
                return "Tactus audio: " + u + " sounds again: the model steps.";
            case POINT_LOST: {
                ListeningPoint p = (ListeningPoint) subject;
                String what = p.kind() == ListeningPoint.Kind.MASS_DISPLACEMENT ? "a mass" : "an interaction";
                return "Tactus audio: " + u + ": listening point " + p + " outputs 0 (" + why + "). The other points "
                        + "keep sounding; it sounds again once " + what + " named \"" + p.element() + "\" is in the "
                        + "model again, or stop it with removeListeningPoint().";
            }
            case POINT_BACK:
                return "Tactus audio: " + u + ": listening point " + subject + " sounds again.";
            case AVATAR_LOST:
                return "Tactus audio: " + u + ": the attached avatar \"" + subject + "\" can no longer be driven (" + why
                        + "): its AvatarExchange now gets zero force while the model keeps sounding. Add a HapticInput3D "
                        + "named \"" + subject + "\" again, or call detachAvatar().";
            case AVATAR_BACK:
                return "Tactus audio: " + u + ": the avatar \"" + subject + "\" is back; the exchange drives it again.";
            case UNEXPECTED:
                return "Tactus audio: " + u + " failed: " + error + " (stack trace below); the samples that fail are "
                        + "written as 0. This is a bug in Tactus or in a PhyUGen subclass; please report it.";
            default:
                return "Tactus audio: " + u + ": more notices than " + subject + "; the next ones are not printed "
                        + "(see isSilenced(), getLastError()).";
        }
    }

    /** @return "PhyUGen", or the subclass's name (a sketch's own class). */
    private static String name(PhyUGen u) {
        String n = u.getClass().getSimpleName();
        return n.isEmpty() ? "PhyUGen" : n;
    }
}
