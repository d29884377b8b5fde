package org.jaria.net.server;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import org.jaria.clock.Clock;

/**
 * Decides who gets a password checked, so that passwords cannot be guessed at network speed:
 *
 * <ul>
 *   <li><b>Per address:</b> after {@code maxFailures} failed logins within {@code windowNanos} of
 *       the first one, that address's logins are refused without checking until the window ends.
 *   <li><b>Over all addresses:</b> at most {@code checksPerSecond} checks a second (a bucket that
 *       holds one second's worth), so guesses rotated over many addresses are no faster than that.
 *       Addresses with a failure in their window may only take the bucket down to half, which
 *       leaves the other half to addresses that have not failed.
 *   <li><b>Known addresses</b> — those a user has logged in from — are not counted in the global
 *       rate (their failures still count per address), so a user who has logged in before is not
 *       slowed by guesses from elsewhere. The connection limits use them too ({@link
 *       PendingAdmission}).
 * </ul>
 *
 * <p>At most {@link #MAX_ADDRESSES} failing and as many known addresses are remembered (a flood of
 * addresses forgets the oldest).
 */
final class LoginLimiter {

  /** Most addresses remembered, of each kind. */
  static final int MAX_ADDRESSES = 4096;

  private record Window(long startNanos, int failures) {}

  /** Why a login is refused without checking its password, or {@link #CHECK} if it may be. */
  enum Verdict {
    CHECK,
    /** The address failed too often lately. */
    ADDRESS_THROTTLED,
    /** Too many passwords are being checked over all addresses. */
    BUSY
  }

  private final Clock clock;
  private final int maxFailures;
  private final long windowNanos;
  private final double checksPerSecond;

  @GuardedBy("this")
  private final Map<String, Window> windows = new HashMap<>();

  @GuardedBy("this")
  private final Map<String, Boolean> known =
      new LinkedHashMap<>(64, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, Boolean> eldest) {
          return size() > MAX_ADDRESSES;
        }
      };

  @GuardedBy("this")
  private double tokens;

  @GuardedBy("this")
  private long refilledNanos;

  LoginLimiter(Clock clock, int maxFailures, long windowNanos, int checksPerSecond) {
    this.clock = clock;
    this.maxFailures = maxFailures;
    this.windowNanos = windowNanos;
    this.checksPerSecond = checksPerSecond;
    this.tokens = checksPerSecond;
    this.refilledNanos = clock.nanoTime();
  }

  /**
   * Whether a login from {@code address} may have its password checked now; if so, the check is
   * counted.
   */
  synchronized Verdict tryCheck(String address) {
    Window w = current(address);
    if (w != null && w.failures() >= maxFailures) {
      return Verdict.ADDRESS_THROTTLED;
    }
    if (known.containsKey(address)) {
      return Verdict.CHECK;
    }
    refill();
    // Addresses that failed lately leave half of the bucket to those that have not.
    double floor = w == null ? 0 : checksPerSecond / 2;
    if (tokens - 1 < floor) {
      return Verdict.BUSY;
    }
    tokens -= 1;
    return Verdict.CHECK;
  }

  /** Whether logins from {@code address} are refused now because it failed too often. */
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

  /** Records a successful login from {@code address}: it is known from now on. */
  synchronized void succeeded(String address) {
    known.put(address, Boolean.TRUE);
  }

  /** Whether a user has logged in from {@code address} (among the last remembered). */
  synchronized boolean isKnown(String address) {
    return known.containsKey(address);
  }

  @GuardedBy("this")
  private void refill() {
    long now = clock.nanoTime();
    tokens = Math.min(checksPerSecond, tokens + (now - refilledNanos) * checksPerSecond / 1e9);
    refilledNanos = now;
  }

  @GuardedBy("this")
  private Window current(String address) {
    Window w = windows.get(address);
    if (w != null && clock.nanoTime() - w.startNanos() >= windowNanos) {
      windows.remove(address);
      return null;
    }
    return w;
  }
}
