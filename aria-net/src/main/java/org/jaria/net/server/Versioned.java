package org.jaria.net.server;

import org.jaria.net.NetEncodable;

/**
 * A published value and its version: equal versions mean equal values, so a client that has seen a
 * version is not sent it again.
 *
 * @param version increases (or at least changes) whenever the value changes
 * @param value the value, or null if there is none yet (nothing is sent)
 */
public record Versioned(long version, NetEncodable value) {

  /** No value yet. */
  public static final Versioned NONE = new Versioned(Long.MIN_VALUE, null);
}
