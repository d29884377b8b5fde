package org.jaria.net.forward;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** ArNetworking's request rule and JAria's stall and reconnection rules, as values. */
class ForwardingRulesTest {

  @Test
  void theNextFrameIsAskedForOnceTheLastIsOlderThanTheInterval() {
    assertFalse(ForwardingRules.shouldRequest(100, false, 5000, 100), "exactly 100 ms: not yet");
    assertTrue(ForwardingRules.shouldRequest(101, false, 5000, 100));
    assertTrue(ForwardingRules.shouldRequest(1, false, 0, 0), "interval 0: as fast as answered");
  }

  @Test
  void anOutstandingRequestIsRepeatedAfterThreeSecondsOnly() {
    assertFalse(ForwardingRules.shouldRequest(60_000, true, 3000, 100), "waits for the answer");
    assertTrue(ForwardingRules.shouldRequest(60_000, true, 3001, 100), "ARIA asks again");
  }

  @Test
  void aServerIsStalledWhenAskedAndSilentForTenSeconds() {
    assertFalse(ForwardingRules.isStalled(false, 60_000), "not asked: not stalled");
    assertFalse(ForwardingRules.isStalled(true, 10_000));
    assertTrue(ForwardingRules.isStalled(true, 10_001));
  }

  @Test
  void theWaitBetweenAttemptsDoublesUpToEightSeconds() {
    assertEquals(0, ForwardingRules.reconnectDelayMs(0));
    assertEquals(500, ForwardingRules.reconnectDelayMs(1));
    assertEquals(1000, ForwardingRules.reconnectDelayMs(2));
    assertEquals(4000, ForwardingRules.reconnectDelayMs(4));
    assertEquals(8000, ForwardingRules.reconnectDelayMs(5));
    assertEquals(8000, ForwardingRules.reconnectDelayMs(Integer.MAX_VALUE), "no overflow");
  }
}
