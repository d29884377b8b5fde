package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.net.ConnectException;
import java.net.InetAddress;
import java.net.Socket;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;

/**
 * When the real-time thread fails, even with an {@link Error}, the world closes its ports (a client
 * is refused instead of connecting to a robot nobody serves) and its exit handler hears it, so
 * {@code jaria sim} ends.
 */
class WorldThreadFailureTest {

  private static void failOnTheWorldThread(Throwable t) throws Exception {
    try (SimWorld w = SimWorld.empty(SimOptions.builder().basePort(0).build())) {
      SimRobot r = w.addRobot("p3dx-sh");
      w.listen();
      int port = r.getPort();
      CompletableFuture<Integer> exit = new CompletableFuture<>();
      w.setExitHandler(exit::complete);
      AtomicBoolean once = new AtomicBoolean(true);
      w.addStepListener(
          () -> {
            if (once.getAndSet(false)) {
              sneakyThrow(t);
            }
          });
      w.startRealTime(1);
      assertEquals(SimWorld.EXIT_WORLD_FAILED, exit.get(30, TimeUnit.SECONDS));
      assertThrows(
          ConnectException.class,
          () -> new Socket(InetAddress.getLoopbackAddress(), port).close(),
          "no port left that accepts and fails");
    }
  }

  @SuppressWarnings("unchecked")
  private static <T extends Throwable> void sneakyThrow(Throwable t) throws T {
    throw (T) t;
  }

  @Test
  void anErrorEndsTheWorldInsteadOfLeavingAZombiePort() throws Exception {
    failOnTheWorldThread(new OutOfMemoryError("test: as when a map's index was too big"));
  }

  @Test
  void aRuntimeExceptionToo() throws Exception {
    failOnTheWorldThread(new IllegalStateException("test: a bug in a tick"));
  }
}
