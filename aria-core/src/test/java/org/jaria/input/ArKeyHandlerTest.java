package org.jaria.input;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.Test;

/** Key bindings, programmatic keys, the reader thread and robot attachment. */
class ArKeyHandlerTest {

  /** A key source fed by the test; blocks up to the timeout like a terminal. */
  private static final class QueueSource implements KeySource {
    final BlockingQueue<Integer> q = new LinkedBlockingQueue<>();
    final AtomicBoolean closed = new AtomicBoolean();

    @Override
    public int read(long timeoutMs) throws java.io.IOException {
      try {
        Integer c = q.poll(timeoutMs, TimeUnit.MILLISECONDS);
        return c == null ? TIMEOUT : c;
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
        throw new java.io.InterruptedIOException("interrupted");
      }
    }

    @Override
    public void close() {
      closed.set(true);
    }
  }

  @Test
  void bindingsAreUniquePerKey() {
    ArKeyHandler k = new ArKeyHandler();
    Runnable a = () -> {};
    Runnable b = () -> {};
    assertTrue(k.addKeyHandler('a', a));
    assertFalse(k.addKeyHandler('a', b), "a key has one handler");
    assertTrue(k.addKeyHandler(ArKeyHandler.UP, a));
    assertTrue(k.remKeyHandler(a), "removes every key bound to it");
    assertNull(k.getKeyHandler('a'));
    assertNull(k.getKeyHandler(ArKeyHandler.UP));
    assertFalse(k.remKeyHandler('a'));
  }

  @Test
  void fedKeysRunTheirHandlersInOrderAtCheckKeys() {
    ArKeyHandler k = new ArKeyHandler();
    List<String> log = new ArrayList<>();
    k.addKeyHandler('1', () -> log.add("one"));
    k.addKeyHandler(ArKeyHandler.SPACE, () -> log.add("space"));
    k.addKeyHandler(
        'x',
        () -> {
          throw new IllegalStateException("bad handler");
        });
    k.feedKey('1');
    k.feedKey('x');
    k.feedKey('z');
    k.feedKey(ArKeyHandler.SPACE);
    assertEquals(List.of(), log, "nothing runs before checkKeys");
    k.checkKeys();
    assertEquals(List.of("one", "space"), log, "a throwing handler does not stop the others");
    k.feedKeys("\033[A1");
    assertEquals(ArKeyHandler.UP, k.getKey());
    assertEquals('1', k.getKey());
    assertEquals(-1, k.getKey());
  }

  @Test
  void attachedHandlersRunInTheRobotsCycleAndEscapeStopsIt() {
    LockstepRig rig = new LockstepRig();
    assertTrue(rig.connect());
    ArKeyHandler k = new ArKeyHandler();
    AtomicBoolean escaped = new AtomicBoolean();
    k.attachKeyHandler(rig.robot, true, () -> escaped.set(true));
    assertNotNull(rig.robot.findSensorInterpTask(ArKeyHandler.TASK_NAME));
    AtomicReference<Long> counterAtKey = new AtomicReference<>();
    k.addKeyHandler('s', () -> counterAtKey.set(rig.robot.getCounter()));
    k.feedKey('s');
    k.feedKey(ArKeyHandler.ESCAPE);
    rig.run(100);
    assertNotNull(counterAtKey.get(), "handled by the cycle");
    assertTrue(escaped.get());
    k.detach();
    assertNull(rig.robot.findSensorInterpTask(ArKeyHandler.TASK_NAME));
    assertNull(k.getKeyHandler(ArKeyHandler.ESCAPE));
  }

  @Test
  void theReaderThreadDecodesDispatchesAndStops() throws Exception {
    QueueSource src = new QueueSource();
    List<Integer> got = Collections.synchronizedList(new ArrayList<>());
    CountDownLatch three = new CountDownLatch(3);
    ArKeyHandler k = new ArKeyHandler(src, "keys-test");
    try {
      assertEquals("keys-test", k.getReaderThreadName());
      assertTrue(k.isReading());
      for (int key : new int[] {ArKeyHandler.UP, ArKeyHandler.ESCAPE, 'q'}) {
        k.addKeyHandler(
            key,
            () -> {
              got.add(key);
              three.countDown();
            });
      }
      for (char c : "\033[Aq\033".toCharArray()) {
        src.q.add((int) c);
      }
      assertTrue(three.await(10, TimeUnit.SECONDS), "three keys, the escape after a pause");
      assertEquals(List.of(ArKeyHandler.UP, (int) 'q', ArKeyHandler.ESCAPE), got);
    } finally {
      k.close();
    }
    assertFalse(k.isReading(), "closed and joined");
    assertTrue(src.closed.get());
  }

  @Test
  void theReaderStopsAtTheEndOfItsSource() throws Exception {
    QueueSource src = new QueueSource();
    ArKeyHandler k = new ArKeyHandler(src, "keys-eof");
    src.q.add(KeySource.EOF);
    assertTrue(k.awaitReaderExit(10_000), "the reader ends with its source");
    k.close();
    assertTrue(src.closed.get());
  }

  @Test
  void keysHaveReadableNames() {
    assertEquals("UP", ArKeyHandler.describe(ArKeyHandler.UP));
    assertEquals("F12", ArKeyHandler.describe(ArKeyHandler.F12));
    assertEquals("'a'", ArKeyHandler.describe('a'));
  }
}
