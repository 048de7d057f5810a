/**
 * Not API (see {@link tactus.internal}): reading a model: state access (positions, forces, the haptic avatar,
 * energies) and the paper engine's index queries.
 */
package tactus.internal.read;
