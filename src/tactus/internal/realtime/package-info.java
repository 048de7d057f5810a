/**
 * Not API (see {@link tactus.internal}): the realtime rule: the lock and the owner's gate, the command queue, the
 * stepping calls and the hand-over between threads (docs/architecture.md, "The ownership rule"). {@link
 * tactus.internal.realtime.ModelLock} lets every facade call in and out and begins and ends the realtime mode;
 * {@link tactus.internal.realtime.Ownership} is the mode itself (the owner, the gate, the queue, the hand-over);
 * {@link tactus.internal.realtime.Stepping} runs the stepping calls in both modes. The modes and their transitions:
 *
 * <pre>{@code
 *                       beginRealtimeStepping()
 *    LOCKED mode  ----------------------------------->  FREE (no owner; a waiting thread
 *       ^                                                 |   ^   applies the queue under the gate)
 *       |                   first stepping call, thread T |   |  a thread waiting for the queue finds
 *       |                                                 v   |  T dead or idle >= 250 ms (under the gate)
 *       |                                              OWNED by T --------------------------------+
 *       |                                                 |   ^   stepping call from U != T:      |
 *       |                                                 |   |   nothing, one message; U takes   |
 *       |                                                 |   +-- the role only if T is dead or   |
 *       |                                                 |       idle >= 250 ms, or U calls      |
 *       |                                                 |       takeRealtimeStepping()          |
 *       |                                                 |       (a PhyUGen): OWNED by U <-------+
 *       |   endRealtimeStepping(), from FREE or OWNED     |
 *       |   (from T inside a call: when that call ends)   v
 *       +-------------------------------------------- ENDING: the queue is applied, the role given up;
 *                                                      the next thread holding the lock switches to LOCKED
 * }</pre>
 */
package tactus.internal.realtime;
