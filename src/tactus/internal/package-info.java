/**
 * Not API: the machinery behind {@link tactus.PhysicalModel}. Everything below {@code tactus.internal} is public
 * only because Java needs it to be for the facade to reach it; it may change in any release, is left out of the
 * published reference, and no sketch or application should import it. The rooms and the directions in which they
 * may use each other are described in docs/architecture.md and checked by {@code PackageDependencyTest}.
 */
package tactus.internal;
