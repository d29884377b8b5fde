package org.jaria.classroom.grading;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * Copies what a student's JVM prints (its standard error, over a pipe) into their output file in
 * the report, keeping at most a given number of bytes and saying how many more there were. A pipe,
 * not the file itself, is what the student's JVM gets: none of its file descriptors names a path of
 * the grader's. One named thread per student, joined when their JVM has ended.
 */
final class OutputCopier {

  private final Thread thread;
  private final InputStream from;
  private volatile IOException failed;

  private OutputCopier(InputStream from, Path to, long max, String name) {
    this.from = from;
    this.thread = new Thread(() -> copy(to, max), name);
    thread.setDaemon(true);
  }

  /** Starts copying {@code from} into {@code to}, keeping at most {@code max} bytes. */
  static OutputCopier start(InputStream from, Path to, long max, String threadName) {
    OutputCopier c = new OutputCopier(from, to, max, threadName);
    c.thread.start();
    return c;
  }

  private void copy(Path to, long max) {
    byte[] buf = new byte[8192];
    long kept = 0;
    long dropped = 0;
    try (OutputStream out = Files.newOutputStream(to)) {
      for (int n = from.read(buf); n >= 0; n = from.read(buf)) {
        int keep = (int) Math.min(n, max - kept);
        if (keep > 0) {
          out.write(buf, 0, keep);
          kept += keep;
        }
        dropped += n - keep;
      }
      if (dropped > 0) {
        out.write(
            ("\n[" + dropped + " more bytes of output were not kept]\n")
                .getBytes(StandardCharsets.UTF_8));
      }
    } catch (IOException e) {
      failed = e;
    }
  }

  /**
   * Waits for the copy to end (the JVM has ended, so its pipe is closing), at most {@code ms};
   * after that the pipe is closed from this side, so nothing still holding it keeps the thread.
   */
  void finish(long ms) {
    try {
      thread.join(ms);
      if (thread.isAlive()) {
        from.close();
        thread.join(TimeUnit.SECONDS.toMillis(2));
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } catch (IOException e) {
      failed = e;
    }
  }

  /** Why the copy failed, or null. */
  IOException failure() {
    return failed;
  }
}
