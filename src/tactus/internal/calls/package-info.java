/**
 * Not API (see {@link tactus.internal}): the second half of each call of {@code PhysicalModel}: enter the model,
 * turn names and indices into ids, hand the work to a room.
 */
package tactus.internal.calls;
