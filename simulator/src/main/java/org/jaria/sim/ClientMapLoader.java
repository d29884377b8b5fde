package org.jaria.sim;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.atomic.AtomicReference;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.sim.world.WorldMap;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Loads the maps clients ask for (SIM_CTRL) on a thread of its own, so a slow disk, a huge file or
 * a file that never ends cannot stall the robots: the world thread hands over a request and picks
 * up the result on a later tick. One load at a time; a request while one is running is refused.
 * What goes to the log says which rule a request broke or which line of a map is wrong, never what
 * the file contains.
 */
final class ClientMapLoader implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(ClientMapLoader.class);

  /**
   * A finished load.
   *
   * @param requested the name the client sent
   * @param robotIndex the robot whose client asked
   * @param map the loaded map, or {@code null} if it could not be loaded
   */
  record Result(String requested, int robotIndex, WorldMap map) {}

  /** Where the bytes of a requested map come from (the map folder, with its checks). */
  @FunctionalInterface
  interface MapBytes {
    /**
     * The bytes of the map {@code requested} names.
     *
     * @throws ClientMapFolder.Refused if the request breaks a rule
     * @throws IOException if the file cannot be read
     */
    byte[] read(String requested) throws IOException;
  }

  private final MapBytes source;
  private final String threadName;
  private final AtomicReference<Result> done = new AtomicReference<>();
  private volatile Thread thread;

  ClientMapLoader(MapBytes source, String threadName) {
    this.source = source;
    this.threadName = threadName;
  }

  /** Whether a load is running or its result has not been picked up. */
  boolean busy() {
    return (thread != null && thread.isAlive()) || done.get() != null;
  }

  /**
   * Starts loading {@code requested} for robot {@code robotIndex}; returns false (and does nothing)
   * if a load is still running.
   */
  boolean submit(String requested, int robotIndex, String robotName) {
    if (busy()) {
      return false;
    }
    thread = new Thread(() -> done.set(load(requested, robotIndex, robotName)), threadName);
    thread.setDaemon(true);
    thread.start();
    return true;
  }

  /** The finished load, once (null while none is finished). */
  Result poll() {
    return done.getAndSet(null);
  }

  /** Waits for a running load to finish (a test's way to stay deterministic). */
  void awaitIdle() throws InterruptedException {
    Thread t = thread;
    if (t != null) {
      t.join();
    }
  }

  private Result load(String requested, int robotIndex, String robotName) {
    String shown = ClientMapFolder.printable(requested);
    try {
      byte[] bytes = source.read(requested);
      ArMap m =
          ArMap.read(
              new InputStreamReader(new ByteArrayInputStream(bytes), StandardCharsets.ISO_8859_1),
              requested);
      log.info("{}: client loaded map '{}'", robotName, shown);
      return new Result(requested, robotIndex, MapSupport.fromArMap(m, "client:" + shown));
    } catch (ClientMapFolder.Refused e) {
      log.warn("{}: client map '{}' refused: {}", robotName, shown, e.getMessage());
    } catch (MapFormatException e) {
      log.warn("{}: client map '{}' is not a valid map (line {})", robotName, shown, e.getLine());
    } catch (MapBudget.MapTooBigException e) {
      log.warn("{}: client map refused: {}", robotName, e.getMessage());
    } catch (IOException e) {
      log.warn(
          "{}: client map '{}' cannot be read ({})",
          robotName,
          shown,
          e.getClass().getSimpleName());
    } catch (RuntimeException | OutOfMemoryError e) {
      log.warn(
          "{}: client map '{}' cannot be loaded ({})", robotName, shown, e.getClass().getName());
    }
    return new Result(requested, robotIndex, null);
  }

  /** Interrupts a load in progress and waits (at most 2 s) for its thread to end. */
  @Override
  public void close() {
    Thread t = thread;
    if (t != null) {
      t.interrupt();
      try {
        t.join(2000);
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
    }
  }
}
