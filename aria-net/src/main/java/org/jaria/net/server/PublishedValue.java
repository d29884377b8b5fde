package org.jaria.net.server;

import java.util.Objects;
import java.util.concurrent.atomic.AtomicReference;
import org.jaria.net.NetEncodable;

/**
 * A {@link Publication} holding the latest value: the producer (typically the robot's cycle) calls
 * {@link #publish} with an immutable snapshot, which costs one atomic write; the server's publisher
 * thread reads it when subscriptions are due.
 */
public final class PublishedValue implements Publication {

  private final AtomicReference<Versioned> latest = new AtomicReference<>(Versioned.NONE);

  /** Publishes a new value (always a new version). */
  public void publish(NetEncodable value) {
    Objects.requireNonNull(value, "value");
    latest.getAndUpdate(v -> new Versioned(v.value() == null ? 1 : v.version() + 1, value));
  }

  /** Publishes {@code value} only if it differs ({@code equals}) from the current one. */
  public void publishIfChanged(NetEncodable value) {
    Objects.requireNonNull(value, "value");
    latest.getAndUpdate(
        v ->
            value.equals(v.value())
                ? v
                : new Versioned(v.value() == null ? 1 : v.version() + 1, value));
  }

  @Override
  public Versioned current() {
    return latest.get();
  }
}
