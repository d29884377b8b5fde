package org.jaria.net;

/**
 * A value that can write itself into a packet: every record of {@code org.jaria.net.data} is one,
 * and so is anything a server publishes.
 */
@FunctionalInterface
public interface NetEncodable {

  /** Appends this value's encoding to {@code out}. */
  void write(ArNetPacket out);
}
