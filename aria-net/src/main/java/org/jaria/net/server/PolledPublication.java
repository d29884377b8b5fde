package org.jaria.net.server;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.Objects;
import java.util.function.LongSupplier;
import java.util.function.Supplier;
import org.jaria.net.NetEncodable;

/**
 * A {@link Publication} that asks a supplier for the value when the server needs it (on the
 * publisher thread, only while someone is subscribed) and gives it a new version whenever it
 * differs from the previous one — for state that lives elsewhere and may be read from any thread: a
 * localizer's estimate, a range device's buffer, a configuration.
 */
public final class PolledPublication implements Publication {

  private final Supplier<? extends NetEncodable> supplier;
  private final LongSupplier key;

  @GuardedBy("this")
  private Versioned last = Versioned.NONE;

  @GuardedBy("this")
  private long lastKey = Long.MIN_VALUE;

  private PolledPublication(Supplier<? extends NetEncodable> supplier, LongSupplier key) {
    this.supplier = Objects.requireNonNull(supplier, "supplier");
    this.key = key;
  }

  /** Polls {@code supplier}; a value that {@code equals} the previous one keeps its version. */
  public static PolledPublication of(Supplier<? extends NetEncodable> supplier) {
    return new PolledPublication(supplier, null);
  }

  /**
   * Polls {@code supplier} only when {@code key} has changed (for example the robot's cycle
   * counter): cheaper when building the value costs more than comparing a number.
   */
  public static PolledPublication keyed(
      LongSupplier key, Supplier<? extends NetEncodable> supplier) {
    return new PolledPublication(supplier, Objects.requireNonNull(key, "key"));
  }

  @Override
  public synchronized Versioned current() {
    if (key != null) {
      long k = key.getAsLong();
      if (k == lastKey && last.value() != null) {
        return last;
      }
      lastKey = k;
    }
    NetEncodable v = supplier.get();
    if (v != null && !v.equals(last.value())) {
      last = new Versioned(last.value() == null ? 1 : last.version() + 1, v);
    }
    return last;
  }
}
