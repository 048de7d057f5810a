package tactus.internal.model;

import tactus.engine.LinkKind;
import tactus.engine.MassKind;

/**
 * Makes and retires the handles of a model's modules (the API's {@code Mass3D}, {@code SpringDamper3D}, ...). The
 * directory keeps them as plain objects, so the machinery never names the API classes that call it; the facade gives
 * the factory and casts what the directory returns. Not API.
 */
public interface HandleFactory {
    /** @return a new handle on a mass of this kind. */
    Object newMass(int id, MassKind kind);

    /** @return a new handle on an interaction of this kind. */
    Object newLink(int id, LinkKind kind);

    /** Marks a handle as no longer part of its model: every later call on it throws. */
    void retire(Object handle);
}
