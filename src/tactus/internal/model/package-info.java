/**
 * Not API (see {@link tactus.internal}): what every room shares: the engine, the directory of names, the clock and
 * units, the paper's leniency, argument checks, the doors into the API's types.
 */
package tactus.internal.model;
