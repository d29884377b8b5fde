package org.jaria.net.server;

import java.util.HashMap;
import java.util.Map;
import org.jaria.clock.Clock;

/**
 * Counts failed logins per address: after {@code maxFailures} failures within {@code windowNanos}
 * of the first one, that address's logins are refused without checking until the window ends, so a
 * password cannot be guessed at network speed. Addresses are forgotten when their window ends, and
 * at most {@link #MAX_ADDRESSES} are remembered (a flood of addresses clears the oldest).
 */
final class LoginLimiter {

  /** Most addresses remembered. */
  static final int MAX_ADDRESSES = 4096;

  private record Window(long startNanos, int failures) {}

  private final Clock clock;
  private final int maxFailures;
  private final long windowNanos;
  private final Map<String, Window> windows = new HashMap<>();

  LoginLimiter(Clock clock, int maxFailures, long windowNanos) {
    this.clock = clock;
    this.maxFailures = maxFailures;
    this.windowNanos = windowNanos;
  }

  /** Whether logins from {@code address} are refused now. */
  synchronized boolean isThrottled(String address) {
    Window w = current(address);
    return w != null && w.failures() >= maxFailures;
  }

  /** Records a failed login from {@code address}. */
  synchronized void failed(String address) {
    Window w = current(address);
    if (w == null) {
      if (windows.size() >= MAX_ADDRESSES) {
        windows.clear();
      }
      windows.put(address, new Window(clock.nanoTime(), 1));
    } else {
      windows.put(address, new Window(w.startNanos(), w.failures() + 1));
    }
  }

  private Window current(String address) {
    Window w = windows.get(address);
    if (w != null && clock.nanoTime() - w.startNanos() >= windowNanos) {
      windows.remove(address);
      return null;
    }
    return w;
  }
}
