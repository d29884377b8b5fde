package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.jaria.net.server.PendingAdmission.Decision;
import org.jaria.net.server.PendingAdmission.Waiting;
import org.junit.jupiter.api.Test;

/** Who may wait to log in, as values: per address, then the global ceiling. */
class PendingAdmissionTest {

  private static Waiting w(String ip, long t, boolean privileged) {
    return new Waiting(ip, t, privileged);
  }

  @Test
  void belowTheLimitsEverybodyWaits() {
    List<Waiting> l = List.of(w("10.0.0.5", 1, false), w("10.0.0.6", 2, false));
    assertEquals(Decision.ACCEPT, PendingAdmission.admit(l, "10.0.0.7", false, 4, 64));
  }

  @Test
  void anAddressAtItsLimitReplacesItsOwnOldest() {
    List<Waiting> l = new ArrayList<>();
    l.add(w("10.0.0.9", 50, false));
    for (int i = 0; i < 4; i++) {
      l.add(w("127.0.0.1", 100 - i, true));
    }
    // Squatters on the loopback renew their sockets; a real user there replaces the oldest.
    assertEquals(Decision.replacing(4), PendingAdmission.admit(l, "127.0.0.1", true, 4, 64));
    // The same rule for anybody, privileged or not: an address only competes with itself.
    List<Waiting> m = List.of(w("10.0.0.9", 7, false), w("10.0.0.9", 3, false));
    assertEquals(Decision.replacing(1), PendingAdmission.admit(m, "10.0.0.9", false, 2, 64));
  }

  @Test
  void atTheCeilingOnlyTheLoopbackAndKnownAddressesGetInByReplacingAStranger() {
    List<Waiting> full = new ArrayList<>();
    for (int i = 0; i < 8; i++) {
      full.add(w("10.1.0." + i, 100 + i, i == 0)); // the oldest is a known address
    }
    assertEquals(
        Decision.REFUSE, PendingAdmission.admit(full, "10.9.9.9", false, 4, 8), "a stranger");
    assertEquals(
        Decision.replacing(1),
        PendingAdmission.admit(full, "127.0.0.1", true, 4, 8),
        "the loopback replaces the oldest stranger, not the known address");
    List<Waiting> allKnown = new ArrayList<>();
    for (int i = 0; i < 8; i++) {
      allKnown.add(w("10.2.0." + i, 200 - i, true));
    }
    assertEquals(
        Decision.replacing(7),
        PendingAdmission.admit(allKnown, "10.3.3.3", true, 4, 8),
        "if every one waiting is privileged, the oldest of all goes");
  }
}
