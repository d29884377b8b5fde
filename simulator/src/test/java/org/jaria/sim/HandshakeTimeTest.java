package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class HandshakeTimeTest {

  @Test
  void aFasterWorldGivesTheClientTheSameRealTime() {
    assertEquals(20_000, HandshakeTime.simulatedMillis(2000, 10));
    assertEquals(3000, HandshakeTime.simulatedMillis(2000, 1.5));
  }

  @Test
  void realTimeSlowerWorldsAndWorldsWithoutAPaceKeepTheLimitAsItIs() {
    assertEquals(2000, HandshakeTime.simulatedMillis(2000, 1));
    assertEquals(2000, HandshakeTime.simulatedMillis(2000, 0.5));
    assertEquals(2000, HandshakeTime.simulatedMillis(2000, 0));
    assertEquals(2000, HandshakeTime.simulatedMillis(2000, -1));
  }

  @Test
  void aWorldRunningTenTimesFasterGivesItsSessionsTenTimesTheSimulatedMilliseconds()
      throws Exception {
    try (SimWorld w = SimWorld.bundled("office", SimOptions.builder().basePort(0).build())) {
      WorldHost host = new WorldHost(w);
      int base = w.getOptions().server().handshakeTimeoutMillis();
      assertEquals(base, host.handshakeTimeoutMillis(), "stepped by hand");
      w.startRealTime(10);
      assertEquals(base * 10, host.handshakeTimeoutMillis(), "ten times real time");
      w.stopRealTime();
      assertEquals(base, host.handshakeTimeoutMillis(), "stepped by hand again");
    }
  }

  @Test
  void aHugeSpeedUpDoesNotOverflow() {
    assertEquals(Integer.MAX_VALUE, HandshakeTime.simulatedMillis(2000, 1e9));
  }
}
