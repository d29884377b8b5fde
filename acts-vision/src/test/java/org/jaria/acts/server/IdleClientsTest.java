package org.jaria.acts.server;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Which ACTS clients go, as values. */
class IdleClientsTest {

  private static IdleClients.View v(long last, boolean spoke) {
    return new IdleClients.View(last, spoke);
  }

  @Test
  void clientsIdlePastTheTimeoutExpire() {
    List<IdleClients.View> c = List.of(v(0, true), v(50, false), v(100, true));
    assertEquals(List.of(0, 1), IdleClients.expired(c, 151, 100));
    assertEquals(List.of(), IdleClients.expired(c, 100, 100));
  }

  @Test
  void aFullServerReplacesTheLongestIdleSilentOrLongIdleClient() {
    assertEquals(
        1,
        IdleClients.toEvict(List.of(v(90, true), v(10, false), v(20, false)), 100, 1000),
        "never spoke, idle longest");
    assertEquals(
        -1,
        IdleClients.toEvict(List.of(v(90, true), v(95, true)), 100, 50),
        "every client busy: nobody replaced");
    assertEquals(0, IdleClients.toEvict(List.of(v(0, true), v(95, true)), 100, 50), "idle a while");
  }
}
