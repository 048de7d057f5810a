package tactus.internal.model;

import java.util.EnumSet;

/**
 * One model's record of the calls of the paper's API that Tactus forgives, as the paper's engine did (a module
 * linked to itself, a subset that was never created, a mass parameter of a ground, ...): by default the call does
 * what the original did (skips the module, or the whole call) and one warning is printed to standard error the
 * first time each kind of problem occurs in the model, naming the call, the element and what was skipped; later
 * ones are forgiven silently (a sketch that makes the call in {@code draw()} does not flood the console). In strict mode
 * ({@link PhysicalModel#setStrict(boolean)}) the same calls throw the {@link IllegalArgumentException} they threw
 * before, with the same message. docs/coming-from-miphysics.md lists every case.
 *
 * <p>Thread-safe. Called from facade calls, on the caller's thread; the engine's stepping never calls it. A ramp of a
 * {@link ParamController} meets it on the thread that triggers the ramp (the realtime path resolves its members
 * there) or, outside realtime stepping, at each ramp step: its {@link ParamController#init(float)} (which a
 * {@link MidiController} calls) prints the warning first, so the steps find it already printed. The only prints left
 * on an audio thread are those of forgiven calls that a sketch makes itself from its audio callback (once each).
 */
public final class PaperLeniency {
    /** The kinds of problem the paper's engine ignored. */
    public enum Kind {
        /** An interaction from a mass to itself. */
        SELF_LINK,
        /** A subset name that was never created. */
        NO_SUCH_SUBSET,
        /** A subset created twice. */
        SUBSET_EXISTS,
        /** A mass or interaction that is not in the model, added to a subset. */
        NO_SUCH_MODULE,
        /** A parameter that the module does not have: the mass of a ground, the stiffness of a Mass3D, ... */
        NO_SUCH_PARAMETER,
        /** A parameter name that is none of "mass", "stiffness", "damping", "dist". */
        UNKNOWN_PARAMETER_NAME,
        /** A haptic-input call on a mass that is not an input module. */
        NOT_AN_INPUT,
        /** An index past the last mass or interaction, in an index getter of the paper's API. */
        INDEX_PAST_THE_END
    }

    private volatile boolean strict;
    private final EnumSet<Kind> warned = EnumSet.noneOf(Kind.class);
    private long forgiven;
    private long printed;

    /** @return true when forgiven calls throw, as before (see {@link PhysicalModel#setStrict(boolean)}). */
    public boolean strict() {
        return strict;
    }

    public void setStrict(boolean strict) {
        this.strict = strict;
    }

    /**
     * Forgives one call, or throws in strict mode.
     *
     * @param kind the kind of problem
     * @param op the call, as the user wrote it (for example "addBubble3D")
     * @param element the element named in the message (a module or subset name)
     * @param problem what is wrong: in strict mode the exception's message is {@code op("element"): problem},
     *     the message the call threw before this class existed
     * @param skipped what the forgiving call did instead (for example "the interaction was not added")
     * @throws IllegalArgumentException in strict mode
     */
    public void forgive(Kind kind, String op, String element, String problem, String skipped) {
        if (strict) {
            throw Check.fail(op, element, problem);
        }
        record(kind, op, element, 0, problem, skipped);
    }

    /**
     * Forgives one call that named an index past the end, as {@link #forgive} does; the messages show {@code op(i)},
     * as the index calls' own exceptions do.
     */
    public void forgiveIndex(String op, int index, String problem, String skipped) {
        if (strict) {
            throw new IllegalArgumentException(op + "(" + index + "): " + problem);
        }
        record(Kind.INDEX_PAST_THE_END, op, null, index, problem, skipped);
    }

    /**
     * Counts a forgiven call and prints its warning if it is the first of its kind (the text is built only then: a
     * call forgiven again costs a count).
     */
    private void record(Kind kind, String op, String element, int index, String problem, String skipped) {
        boolean first;
        synchronized (warned) {
            forgiven++;
            first = warned.add(kind);
            if (first) {
                printed++;
            }
        }
        if (first) {
            String call = element == null ? op + "(" + index + ")" : op + "(\"" + element + "\")";
            System.err.println(warning(call, problem, skipped));
            System.err.flush();
        }
    }

    /** @return the text printed the first time a kind of problem occurs; {@code call} is for example op("name"). */
    public static String warning(String call, String problem, String skipped) {
        return "Tactus: " + call + ": " + problem + "; " + skipped + ", as the paper's engine did (printed once per"
                + " model for this kind of problem; PhysicalModel.setStrict(true) makes it an exception)";
    }

    /** @return the number of calls forgiven so far. */
    public long forgivenCount() {
        synchronized (warned) {
            return forgiven;
        }
    }

    /** @return the number of warnings printed so far. */
    public long warningCount() {
        synchronized (warned) {
            return printed;
        }
    }
}
