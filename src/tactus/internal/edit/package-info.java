/**
 * Not API (see {@link tactus.internal}): building and editing a model: modules, parameters, subsets and contact
 * groups, topology, oscillator tuning.
 */
package tactus.internal.edit;
