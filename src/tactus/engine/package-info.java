/**
 * The simulation engine: flat structure-of-arrays state, one kernel per module kind, the
 * compiled step plan, unit conversions and energy measures.
 *
 * <p>The engine depends on the JDK only. It works in algorithmic units (coefficients per
 * simulation step) and addresses modules by integer ids; names, SI units, handles and
 * locking belong to the {@code tactus} facade. A step is the explicit two-phase scheme of
 * mass-interaction physics: all masses move using the forces of the previous step, then all
 * interactions compute new forces from the new positions (a one-sample force delay).
 */
package tactus.engine;
