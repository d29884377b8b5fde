package org.jaria.apps.fx;

import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.logging.Level;
import java.util.logging.Logger;
import javafx.application.Platform;

/**
 * Starting JavaFX from a command line program, with or without a display.
 *
 * <p>The {@code jaria} launcher puts JavaFX on the class path (not the module path) and starts the
 * apps from picocli commands rather than through {@code Application.launch}, so the toolkit is
 * started here with {@link Platform#startup(Runnable)}. JavaFX then warns "Unsupported JavaFX
 * configuration", which is harmless for this use; {@link #startup()} keeps that warning quiet.
 *
 * <p>{@link #configureHeadless()} selects Monocle's Headless platform with software rendering
 * before the toolkit starts: windows then render into memory, which is how {@code jaria screenshot}
 * and the tests work on machines without a display.
 */
public final class FxRuntime {

  private static final Object LOCK = new Object();

  /**
   * JavaFX's own logger (java.util.logging, through System.Logger). Held here so the level set in
   * {@link #startup()} stays: the logging framework keeps loggers only weakly.
   */
  private static final Logger JAVAFX_LOG = Logger.getLogger("javafx");

  private FxRuntime() {}

  /**
   * Makes the next toolkit start use Monocle's Headless platform and software rendering. Has no
   * effect once the toolkit runs; properties already set (e.g. by the test configuration) are kept.
   */
  public static void configureHeadless() {
    setIfAbsent("glass.platform", "Monocle");
    setIfAbsent("monocle.platform", "Headless");
    setIfAbsent("prism.order", "sw");
    setIfAbsent("prism.text", "t2k");
    setIfAbsent("java.awt.headless", "true");
    setIfAbsent("testfx.robot", "glass");
    setIfAbsent("testfx.headless", "true");
  }

  /** Whether the toolkit was (or will be) started on Monocle's Headless platform. */
  public static boolean isHeadless() {
    return "Headless".equalsIgnoreCase(System.getProperty("monocle.platform"))
        && "Monocle".equalsIgnoreCase(System.getProperty("glass.platform"));
  }

  private static void setIfAbsent(String key, String value) {
    if (System.getProperty(key) == null) {
      System.setProperty(key, value);
    }
  }

  /**
   * Starts the JavaFX toolkit if it is not running yet, and keeps it running when the last window
   * closes (the caller decides when to {@link Platform#exit()}). Safe to call many times.
   */
  public static void startup() {
    synchronized (LOCK) {
      CountDownLatch started = new CountDownLatch(1);
      if (JAVAFX_LOG.getLevel() == null) {
        // Only the class-path warning is logged at WARNING on start-up; errors still show.
        JAVAFX_LOG.setLevel(Level.SEVERE);
      }
      try {
        Platform.startup(started::countDown);
      } catch (IllegalStateException alreadyRunning) {
        started.countDown();
      } catch (UnsupportedOperationException | UnsatisfiedLinkError e) {
        throw new IllegalStateException(
            "JavaFX cannot open a window here ("
                + e.getMessage()
                + "): "
                + GuiCheck.problem()
                    .orElse(
                        "check that a desktop is running and the GTK 3 libraries are installed"
                            + " (sudo apt-get install libgtk-3-0), or render the window to a file"
                            + " with ./jaria screenshot APP ... -o FILE.png"),
            e);
      }
      try {
        started.await();
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
        throw new IllegalStateException("interrupted while JavaFX started", e);
      }
      Platform.setImplicitExit(false);
    }
  }

  /**
   * Runs {@code work} on the JavaFX application thread and returns its result, waiting at most
   * {@code timeoutSeconds}. Runs it directly when called on that thread.
   *
   * @throws IllegalStateException if the work failed or timed out (the cause says why)
   */
  public static <T> T call(Callable<T> work, long timeoutSeconds) {
    if (Platform.isFxApplicationThread()) {
      try {
        return work.call();
      } catch (RuntimeException e) {
        throw e;
      } catch (Exception e) {
        throw new IllegalStateException(e.getMessage(), e);
      }
    }
    CompletableFuture<T> f = new CompletableFuture<>();
    Platform.runLater(
        () -> {
          try {
            f.complete(work.call());
          } catch (Throwable t) {
            f.completeExceptionally(t);
          }
        });
    try {
      return f.get(timeoutSeconds, TimeUnit.SECONDS);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new IllegalStateException("interrupted while waiting for the JavaFX thread", e);
    } catch (ExecutionException e) {
      Throwable c = e.getCause();
      if (c instanceof RuntimeException r) {
        throw r;
      }
      throw new IllegalStateException(c.getMessage(), c);
    } catch (TimeoutException e) {
      throw new IllegalStateException(
          "the JavaFX thread did not answer within " + timeoutSeconds + " s (is it blocked?)", e);
    }
  }

  /** Runs {@code work} on the JavaFX application thread and waits for it (see {@link #call}). */
  public static void run(Runnable work, long timeoutSeconds) {
    call(
        () -> {
          work.run();
          return null;
        },
        timeoutSeconds);
  }
}
