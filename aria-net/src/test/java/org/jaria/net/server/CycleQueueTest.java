package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.LongAdder;
import org.junit.jupiter.api.Test;

/**
 * The rules of the queue in front of the robot's cycle, as values: what runs, in which order, what
 * is replaced and what a stop does to the work around it.
 */
class CycleQueueTest {

  private final List<String> log = new ArrayList<>();
  private final LongAdder superseded = new LongAdder();
  private final LongAdder reasserted = new LongAdder();
  private final CycleQueue q = new CycleQueue(4, superseded, reasserted);

  private CycleQueue.Work work(String name) {
    return new CycleQueue.Work(
        () -> log.add(name), () -> log.add("ack " + name), () -> log.add("again " + name));
  }

  private void drain(int max) {
    q.drain(max, Runnable::run);
  }

  @Test
  void plainWorkRunsInOrderAndIsBounded() {
    for (int i = 1; i <= 4; i++) {
      assertTrue(q.offer(work("w" + i), i));
    }
    assertFalse(q.offer(work("w5"), 5), "the fifth waits for room");
    drain(3);
    assertEquals(List.of("w1", "w2", "w3"), log);
    assertTrue(q.offer(work("w6"), 6));
    drain(10);
    assertEquals(List.of("w1", "w2", "w3", "w4", "w6"), log);
    assertEquals(0, q.size());
  }

  @Test
  void aNewerLatestWinsRequestReplacesTheWaitingOneAndAcknowledgesIt() {
    for (int i = 1; i <= 500; i++) {
      q.offerLatest("a/ratioDrive", work("drive" + i), i);
    }
    q.offerLatest("b/ratioDrive", work("b-drive"), 501);
    assertEquals(2, q.size(), "one waiting per client, however many were sent");
    assertEquals(499, superseded.sum());
    assertEquals("ack drive1", log.get(0), "a replaced request counts as done");
    log.clear();
    drain(10);
    assertEquals(List.of("drive500", "b-drive"), log);
  }

  @Test
  void latestWinsAndSafetyRequestsAreNeverRefusedForRoom() {
    for (int i = 1; i <= 4; i++) {
      assertTrue(q.offer(work("w" + i), i));
    }
    q.offerLatest("a/ratioDrive", work("drive"), 5);
    q.offerSafety("a/stop", work("stop"), 6);
    assertEquals(6, q.size());
  }

  @Test
  void aStopRunsAtTheNextDrainAfterWhatCameBeforeItAndMakesTheDrivesBeforeItMoot() {
    q.offer(work("goto"), 1);
    q.offerLatest("a/ratioDrive", work("drive"), 2);
    q.offer(work("enableMotors"), 3);
    q.offerSafety("a/stop", work("stop"), 4);
    q.offer(work("wander"), 5);
    // Even with room for a single command per cycle, the stop and what preceded it run now.
    drain(1);
    assertEquals(List.of("ack drive", "goto", "enableMotors", "stop", "wander"), log);
    assertEquals(1, superseded.sum());
  }

  @Test
  void repeatedStopsOfOneClientCollapse() {
    for (int i = 1; i <= 1000; i++) {
      q.offerSafety("a/stop", work("stop" + i), i);
    }
    assertEquals(1, q.size());
    log.clear();
    drain(0);
    assertEquals(List.of("stop1000"), log);
  }

  @Test
  void workOfARequestSentBeforeTheStopThatArrivesAfterItIsFollowedByTheStopAgain() {
    q.offerSafety("a/stop", work("stop"), 10);
    drain(5);
    // A worker finishes a goto asked for before the stop (sequence 7) and queues its activation.
    q.offer(work("activate goto"), 7);
    q.offer(work("service task"), CycleQueue.NOT_A_REQUEST);
    drain(5);
    assertEquals(List.of("stop", "activate goto", "again stop", "service task"), log);
    assertEquals(1, reasserted.sum());
  }

  @Test
  void lateWorkIsDroppedOnceSomethingNewerThanTheStopHasBeenApplied() {
    q.offerSafety("a/stop", work("stop"), 10);
    q.offer(work("newer goto"), 11);
    drain(5);
    q.offer(work("activate old goto"), 7);
    drain(5);
    assertEquals(List.of("stop", "newer goto", "ack activate old goto"), log);
    assertEquals(0, reasserted.sum());
  }
}
