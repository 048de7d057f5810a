package tactus.internal.model;

import tactus.engine.LinkKind;
import tactus.engine.MassKind;

/**
 * Told by the directory, by module id, when a module joins or leaves a model (the API keeps its handles through it,
 * so that the machinery never names them). Called inside the change, by the thread that makes it. Not API.
 */
public interface ModuleListener {
    /** A mass joined the model under {@code id}, or its kind changed (a new stamp: the old handle is gone). */
    void massAdded(int id, MassKind kind, int stamp);

    /** An interaction joined the model under {@code id}. */
    void linkAdded(int id, LinkKind kind);

    /** The mass {@code id} left the model (or is about to take a new kind). */
    void massGone(int id);

    /** The interaction {@code id} left the model. */
    void linkGone(int id);
}
