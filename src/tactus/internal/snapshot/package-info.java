/**
 * Not API (see {@link tactus.internal}): the render snapshot, copied only for a reader: the writer that decides
 * when to publish, and the lock-free triple buffer between the stepping thread and the drawing thread.
 */
package tactus.internal.snapshot;
