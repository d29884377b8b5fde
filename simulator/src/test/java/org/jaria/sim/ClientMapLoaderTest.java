package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** A map load that takes as long as it likes never holds up the thread that asked for it. */
class ClientMapLoaderTest {

  @Test
  void aSlowLoadRunsOnItsOwnThreadAndOneAtATime() throws Exception {
    CountDownLatch started = new CountDownLatch(1);
    CountDownLatch release = new CountDownLatch(1);
    ClientMapLoader loader =
        new ClientMapLoader(
            name -> {
              started.countDown();
              try {
                release.await();
              } catch (InterruptedException e) {
                throw new java.io.InterruptedIOException("closed");
              }
              return "2D-Map\nLINES\n0 0 1000 0\nDATA\n".getBytes(StandardCharsets.ISO_8859_1);
            },
            "test-map-loader");
    try (loader) {
      assertTrue(loader.submit("slow.map", 0, "robot"), "returns at once");
      assertTrue(started.await(10, TimeUnit.SECONDS));
      assertTrue(loader.busy());
      assertFalse(loader.submit("other.map", 0, "robot"), "one load at a time");
      assertNull(loader.poll(), "nothing finished while the file is still being read");
      release.countDown();
      loader.awaitIdle();
      ClientMapLoader.Result r = loader.poll();
      assertNotNull(r);
      assertEquals("slow.map", r.requested());
      assertEquals(1, r.map().lines().size());
      assertFalse(loader.busy());
    }
  }

  @Test
  void closingAbandonsALoadThatNeverEnds() throws Exception {
    CountDownLatch started = new CountDownLatch(1);
    ClientMapLoader loader =
        new ClientMapLoader(
            name -> {
              started.countDown();
              try {
                new CountDownLatch(1).await();
              } catch (InterruptedException e) {
                throw new java.io.InterruptedIOException("closed");
              }
              return new byte[0];
            },
            "test-map-loader-2");
    loader.submit("never.map", 0, "robot");
    assertTrue(started.await(10, TimeUnit.SECONDS));
    loader.close();
    loader.awaitIdle();
    ClientMapLoader.Result r = loader.poll();
    assertNotNull(r);
    assertNull(r.map(), "an abandoned load is a failed one");
  }
}
