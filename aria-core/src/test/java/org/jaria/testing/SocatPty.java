package org.jaria.testing;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardWatchEventKinds;
import java.nio.file.WatchKey;
import java.nio.file.WatchService;
import java.time.Duration;
import java.util.concurrent.TimeUnit;

/**
 * A pair of linked pseudo-terminals made by socat: bytes written to one come out of the other,
 * through the kernel's real tty layer, as between a computer's serial port and a robot. socat must
 * be installed ({@code .ci/run} installs it).
 */
public final class SocatPty implements AutoCloseable {

  /** How long socat may take to create both ends before the test gives up. */
  private static final Duration STARTUP = Duration.ofSeconds(10);

  /** Longest wait for a file event before checking that socat is still alive. */
  private static final long CHECK_ALIVE_NANOS = TimeUnit.MILLISECONDS.toNanos(200);

  /** One end (give it to the client). */
  public final Path a;

  /** The other end (give it to the robot); null when the other end is a TCP connection. */
  public final Path b;

  private final Process process;

  /**
   * Starts socat with its links in {@code dir}; returns once both ends exist.
   *
   * @throws IOException if socat is missing, exits, or has not made both links within 10 s
   */
  public SocatPty(Path dir) throws IOException, InterruptedException {
    this(dir, dir.resolve("ttyA"), dir.resolve("ttyB"), null);
  }

  /**
   * A serial port whose other end is a TCP connection to {@code host:port}: a robot program opens
   * {@link #a} as a serial port and talks to, say, a simulator, through the real tty layer as it
   * would to a Pioneer's serial port. {@link #b} is null.
   */
  public static SocatPty bridgedToTcp(Path dir, String host, int port)
      throws IOException, InterruptedException {
    return new SocatPty(dir, dir.resolve("ttyA"), null, "TCP:" + host + ":" + port);
  }

  private SocatPty(Path dir, Path a, Path b, String otherAddress)
      throws IOException, InterruptedException {
    this.a = a;
    this.b = b;
    Path log = dir.resolve("socat.log");
    String second = b != null ? "pty,raw,echo=0,link=" + b : otherAddress;
    // Watch the folder before socat starts, so the creation of a link cannot be missed.
    try (WatchService watcher = dir.getFileSystem().newWatchService()) {
      dir.register(watcher, StandardWatchEventKinds.ENTRY_CREATE);
      process =
          new ProcessBuilder("socat", "pty,raw,echo=0,link=" + a, second)
              .redirectErrorStream(true)
              .redirectOutput(log.toFile())
              .start();
      long deadline = System.nanoTime() + STARTUP.toNanos();
      while (!(Files.exists(a) && (b == null || Files.exists(b)))) {
        long left = deadline - System.nanoTime();
        if (!process.isAlive() || left <= 0) {
          process.destroy();
          throw new IOException(
              "socat did not create the pty within "
                  + STARTUP.toSeconds()
                  + " s (is socat installed? apt-get install socat): "
                  + Files.readString(log));
        }
        // Woken by the next file created in the folder; the cap only lets a socat that died
        // without creating anything be noticed before the deadline.
        WatchKey key = watcher.poll(Math.min(left, CHECK_ALIVE_NANOS), TimeUnit.NANOSECONDS);
        if (key != null) {
          key.pollEvents();
          key.reset();
        }
      }
    }
  }

  @Override
  public void close() {
    process.destroy();
    try {
      process.waitFor(5, TimeUnit.SECONDS);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }
}
