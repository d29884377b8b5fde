package org.jaria.sim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class LogRateLimitTest {

  @Test
  void aFloodGivesOneLinePerIntervalSayingHowManyWereNotLogged() {
    LogRateLimit l = new LogRateLimit(10_000);
    assertEquals(0, l.record(0), "the first is logged at once");
    int logged = 0;
    for (long t = 1; t < 10_000; t++) {
      if (l.record(t) >= 0) {
        logged++;
      }
    }
    assertEquals(0, logged, "9999 more within the interval: none logged");
    assertEquals(9_999, l.record(10_000), "the next line says how many were not");
    assertEquals(-1, l.record(10_001));
    assertEquals(1, l.record(25_000));
  }

  @Test
  void intervalZeroLogsEverything() {
    LogRateLimit l = new LogRateLimit(0);
    for (int i = 0; i < 5; i++) {
      assertEquals(0, l.record(i));
    }
  }
}
