package org.jaria.net.server;

/**
 * Data a server publishes: clients subscribe to it at a rate, or ask for it once. The server asks
 * for {@link #current()} on its publisher thread when some subscription is due, encodes the value
 * once per version, and sends the same bytes to every client whose subscription is due and has not
 * seen that version yet.
 *
 * <p>Implementations must be thread-safe and cheap: typically they return an immutable snapshot
 * that the robot's cycle (or a provider) stored. {@link PublishedValue} is a ready-made one.
 */
@FunctionalInterface
public interface Publication {

  /** The current value and its version (a changed value must come with a new version). */
  Versioned current();
}
