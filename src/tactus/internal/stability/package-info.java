/**
 * Not API (see {@link tactus.internal}): stability: the guard that analyses every change, the divergence watch and
 * the messages that name the culprit.
 */
package tactus.internal.stability;
