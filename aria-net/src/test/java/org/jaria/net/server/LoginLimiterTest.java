package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import org.jaria.clock.VirtualClock;
import org.jaria.net.server.LoginLimiter.Verdict;
import org.junit.jupiter.api.Test;

/** Who gets a password checked: per address, over all addresses, and known addresses. */
class LoginLimiterTest {

  private final VirtualClock clock = new VirtualClock();
  private final LoginLimiter limiter =
      new LoginLimiter(clock, 5, Duration.ofMinutes(1).toNanos(), 20);

  @Test
  void anAddressThatFailsFiveTimesIsThrottledForTheWindow() {
    for (int i = 0; i < 5; i++) {
      assertEquals(Verdict.CHECK, limiter.tryCheck("10.0.0.1"));
      limiter.failed("10.0.0.1");
      clock.advance(Duration.ofSeconds(1));
    }
    assertEquals(Verdict.ADDRESS_THROTTLED, limiter.tryCheck("10.0.0.1"));
    clock.advance(Duration.ofSeconds(56));
    assertEquals(Verdict.CHECK, limiter.tryCheck("10.0.0.1"), "the window has passed");
  }

  @Test
  void guessesRotatedOverManyAddressesGetAtMostTheGlobalRate() {
    // 3,700 guesses a second, each from a new address of 127.0.0.0/8 (the attack).
    int checked = 0;
    for (int i = 0; i < 3700 * 5; i++) {
      String ip = "127." + (i >> 16 & 255) + "." + (i >> 8 & 255) + "." + (i & 255);
      if (limiter.tryCheck(ip) == Verdict.CHECK) {
        checked++;
        limiter.failed(ip);
      }
      clock.advance(Duration.ofNanos(1_000_000_000L / 3700));
    }
    // A full bucket to start with, then 20 a second.
    assertEquals(20 + 20 * 5, checked, 2);
  }

  @Test
  void addressesThatFailedTakeOnlyHalfTheBudgetAndKnownOnesAreNotCounted() {
    limiter.failed("10.6.6.6");
    int bad = 0;
    while (limiter.tryCheck("10.6.6.6") == Verdict.CHECK) {
      bad++;
    }
    assertEquals(10, bad, "a failing address stops at half the bucket");
    int clean = 0;
    for (int i = 0; limiter.tryCheck("10.7.0." + i) == Verdict.CHECK; i++) {
      clean++;
    }
    assertEquals(10, clean, "the other half is left to addresses that have not failed");
    assertEquals(Verdict.BUSY, limiter.tryCheck("10.8.8.8"));
    limiter.succeeded("192.168.1.20");
    assertEquals(Verdict.CHECK, limiter.tryCheck("192.168.1.20"), "a known address is not slowed");
  }
}
