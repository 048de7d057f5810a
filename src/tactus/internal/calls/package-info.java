/**
 * Not API (see {@link tactus.internal}): the second half of each call of {@code PhysicalModel} and of its handles
 * ({@code ModuleCalls}, by module id): enter the model through its one door ({@code ModelLock}), turn names and
 * indices into ids, hand the work to a room. The calls return module ids, never handles.
 */
package tactus.internal.calls;
