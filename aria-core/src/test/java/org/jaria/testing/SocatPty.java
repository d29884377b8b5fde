package org.jaria.testing;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * A pair of linked pseudo-terminals made by socat: bytes written to one come out of the other,
 * through the kernel's real tty layer, as between a computer's serial port and a robot. socat must
 * be installed ({@code .ci/run} installs it).
 */
public final class SocatPty implements AutoCloseable {

  /** One end (give it to the client). */
  public final Path a;

  /** The other end (give it to the robot). */
  public final Path b;

  private final Process process;

  /** Starts socat with its links in {@code dir}; returns once both ends exist. */
  public SocatPty(Path dir) throws IOException, InterruptedException {
    a = dir.resolve("ttyA");
    b = dir.resolve("ttyB");
    process =
        new ProcessBuilder("socat", "pty,raw,echo=0,link=" + a, "pty,raw,echo=0,link=" + b)
            .redirectErrorStream(true)
            .redirectOutput(dir.resolve("socat.log").toFile())
            .start();
    long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
    while (!(Files.exists(a) && Files.exists(b))) {
      if (!process.isAlive() || System.nanoTime() > end) {
        throw new IOException(
            "socat did not create the pty pair (is socat installed? apt-get install socat): "
                + Files.readString(dir.resolve("socat.log")));
      }
      // socat needs a moment to create both links; poll the file system, not the clock
      process.waitFor(10, TimeUnit.MILLISECONDS);
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
