package org.jaria.apps.fx;

import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import javafx.application.Platform;
import javafx.beans.property.DoubleProperty;
import javafx.beans.property.ReadOnlyBooleanProperty;
import javafx.beans.property.ReadOnlyBooleanWrapper;
import javafx.beans.property.ReadOnlyStringProperty;
import javafx.beans.property.ReadOnlyStringWrapper;
import javafx.beans.property.SimpleDoubleProperty;

/**
 * Runs an app's long operations (loading a big map, saving, training on a large image) on one named
 * worker thread, so the window never freezes. While work runs, {@link #busyProperty()} is true and
 * {@link #messageProperty()} says what is being done: bind a progress indicator to them. Results
 * and errors come back on the JavaFX thread.
 *
 * <p>One worker thread runs the jobs in order, so jobs of one app never race each other. {@link
 * #close()} stops it and waits for the job in progress.
 */
public final class BackgroundWork implements AutoCloseable {

  private final ExecutorService executor;
  private final ReadOnlyBooleanWrapper busy = new ReadOnlyBooleanWrapper(false);
  private final ReadOnlyStringWrapper message = new ReadOnlyStringWrapper("");
  private final DoubleProperty progress = new SimpleDoubleProperty(-1);
  private final AtomicInteger pending = new AtomicInteger();
  private final Object idleLock = new Object();

  /** A worker whose thread is called {@code threadName}. */
  public BackgroundWork(String threadName) {
    executor =
        Executors.newSingleThreadExecutor(
            r -> {
              Thread t = new Thread(r, threadName);
              t.setDaemon(true);
              return t;
            });
  }

  /** True while a job is queued or running (JavaFX thread). */
  public ReadOnlyBooleanProperty busyProperty() {
    return busy.getReadOnlyProperty();
  }

  /** What the current job does, e.g. "Loading columbia.map" (JavaFX thread). */
  public ReadOnlyStringProperty messageProperty() {
    return message.getReadOnlyProperty();
  }

  /** Progress 0..1 of the current job, or -1 when unknown (JavaFX thread). */
  public DoubleProperty progressProperty() {
    return progress;
  }

  /**
   * Runs {@code job} on the worker thread.
   *
   * @param what what the job does, for the status line
   * @param job the work; runs off the JavaFX thread and must not touch the scene
   * @param onSuccess receives the result on the JavaFX thread
   * @param onError receives the failure on the JavaFX thread
   */
  public <T> void submit(
      String what, Callable<T> job, Consumer<? super T> onSuccess, Consumer<Exception> onError) {
    pending.incrementAndGet();
    busy.set(true);
    message.set(what);
    progress.set(-1);
    executor.execute(
        () -> {
          T result = null;
          Exception failure = null;
          try {
            result = job.call();
          } catch (Exception e) {
            failure = e;
          } catch (LinkageError | AssertionError | OutOfMemoryError e) {
            // Reported like any failure, so the window never waits forever for this job.
            failure = new IllegalStateException(e.toString(), e);
          }
          T r = result;
          Exception f = failure;
          Platform.runLater(
              () -> {
                try {
                  if (f == null) {
                    onSuccess.accept(r);
                  } else {
                    onError.accept(f);
                  }
                } finally {
                  finished();
                }
              });
        });
  }

  /** Runs {@code job} on the worker thread with no result to deliver. */
  public void submit(String what, Runnable job, Consumer<Exception> onError) {
    submit(
        what,
        () -> {
          job.run();
          return null;
        },
        r -> {},
        onError);
  }

  private void finished() {
    if (pending.decrementAndGet() == 0) {
      busy.set(false);
      message.set("");
      progress.set(-1);
    }
    synchronized (idleLock) {
      idleLock.notifyAll();
    }
  }

  /**
   * Waits until every submitted job has finished and delivered its result (for tests and
   * screenshots; never call it on the JavaFX thread, which delivers the results).
   *
   * @return false if that did not happen within the timeout
   */
  public boolean awaitIdle(long timeout, TimeUnit unit) throws InterruptedException {
    if (Platform.isFxApplicationThread()) {
      throw new IllegalStateException("awaitIdle would block the JavaFX thread that it waits for");
    }
    long deadline = System.nanoTime() + unit.toNanos(timeout);
    synchronized (idleLock) {
      while (pending.get() > 0) {
        long left = deadline - System.nanoTime();
        if (left <= 0) {
          return false;
        }
        TimeUnit.NANOSECONDS.timedWait(idleLock, left);
      }
    }
    return true;
  }

  /** Stops the worker after the job in progress (queued jobs are dropped) and waits for it. */
  @Override
  public void close() {
    executor.shutdownNow();
    try {
      if (!executor.awaitTermination(10, TimeUnit.SECONDS)) {
        throw new IllegalStateException("a background job did not stop within 10 s");
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }
}
