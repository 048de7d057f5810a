/**
 * Not API (see {@link tactus.internal}): the realtime rule: the lock and the owner's gate, the command queue, the
 * stepping calls and the hand-over between threads (docs/architecture.md, "The ownership rule").
 */
package tactus.internal.realtime;
