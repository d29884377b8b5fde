package org.jaria.classroom.grading;

import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import org.jaria.clock.VirtualClock;
import org.jaria.robot.ArRobot;

/**
 * The student's sequential program on its own thread in the student's JVM, handed control in
 * lockstep: after it is started, and on every tick, the harness waits until the program waits on
 * the robot's clock again, ends, or has computed for {@link Programs#STUCK_AFTER} of real time
 * without waiting (stuck). Only the harness's thread calls it.
 */
final class StudentProgram {

  /** Program states as sent in a STATE frame. */
  static final int NONE = 0;

  static final int RUNNING = 1;
  static final int FINISHED = 2;
  static final int FAILED = 3;
  static final int STUCK = 4;

  private final VirtualClock clock;
  private final AtomicBoolean finished = new AtomicBoolean();
  private Programs.Body body;
  private Thread thread;
  private volatile Throwable failure;
  private int state = NONE;
  private String message = "";
  private Consumer<OutOfMemoryError> onResourceError = e -> {};

  StudentProgram(VirtualClock clock) {
    this.clock = clock;
  }

  /** What to do when the program runs out of memory or threads. */
  void onResourceError(Consumer<OutOfMemoryError> action) {
    onResourceError = action;
  }

  /** The program the student's side set up (none: starting it finishes at once). */
  void set(Programs.Body program) {
    body = program;
  }

  /** Its state, one of the constants above. */
  int state() {
    return state;
  }

  /** What it threw, described for the student, or empty. */
  String message() {
    return message;
  }

  /** Starts it on {@code robot} and waits until it waits on the clock, ends or is stuck. */
  void start(ArRobot robot) {
    if (body == null) {
      failure = null;
      state = FINISHED;
      return;
    }
    finished.set(false);
    failure = null;
    Programs.Body b = body;
    Thread t =
        new Thread(
            () -> {
              try {
                b.run(robot);
              } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
              } catch (OutOfMemoryError e) {
                failure = e;
                onResourceError.accept(e);
              } catch (RuntimeException | Error e) {
                failure = e;
                System.err.println("your program threw " + Solutions.describe(e));
              } finally {
                finished.set(true);
                clock.wakeWatchers(); // hand control back at once
              }
            },
            "program-" + robot.getName());
    t.setDaemon(true);
    thread = t;
    state = RUNNING;
    t.start();
    await();
  }

  /** Waits until the program waits on the clock, ends, or is stuck. */
  void await() {
    boolean waiting;
    try {
      waiting = clock.awaitWaiters(1, Programs.STUCK_AFTER, finished::get);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      waiting = false;
    }
    if (finished.get()) {
      joinQuietly(thread);
      Throwable f = failure;
      state = f == null ? FINISHED : FAILED;
      message = f == null ? "" : Solutions.describe(f);
    } else if (!waiting) {
      state = STUCK;
      thread.interrupt();
    }
  }

  /** Interrupts a running program. */
  void stop() {
    if (state == RUNNING && thread != null) {
      thread.interrupt();
      state = NONE;
    }
  }

  private static void joinQuietly(Thread t) {
    try {
      t.join(Programs.STUCK_AFTER.toMillis());
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }
}
