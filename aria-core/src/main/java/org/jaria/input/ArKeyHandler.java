package org.jaria.input;

import java.io.IOException;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicReference;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs code when keys are pressed (ARIA's {@code ArKeyHandler}). Bind a key to a {@link Runnable}
 * with {@link #addKeyHandler}; keys are ordinary characters ({@code 'a'}, {@code '1'}) or the
 * constants here for special keys ({@link #UP}, {@link #SPACE}, {@link #ESCAPE} ...).
 *
 * <p>Keys arrive from a {@link KeySource} read by a thread of this handler (for a terminal use
 * {@link #forTerminal()}), or are fed by a program with {@link #feedKey} (a GUI, a test). They are
 * queued and handled by {@link #checkKeys()}:
 *
 * <ul>
 *   <li>attached to a robot ({@link #attachKeyHandler(ArRobot, boolean, Runnable)}), {@code
 *       checkKeys} runs every cycle as a sensor-interpretation task, so handlers run on the robot's
 *       cycle thread with the robot locked, like ARIA;
 *   <li>not attached, the reader thread runs {@code checkKeys} itself after each key; a program
 *       that only feeds keys calls {@code checkKeys} when it likes.
 * </ul>
 *
 * <pre>{@code
 * try (ArKeyHandler keys = ArKeyHandler.forTerminal()) {
 *   keys.attachKeyHandler(robot, true, done::countDown);   // Escape: stop and tell main
 *   keys.addKeyHandler(ArKeyHandler.SPACE, robot::stop);
 *   keys.addKeyHandler('1', () -> robot.setRotVel(10));
 *   done.await();
 * }
 * }</pre>
 *
 * <p>Unlike ARIA there is no global key handler: pass the handler to whatever needs it ({@link
 * org.jaria.action.ArActionKeydrive}). Escape never exits the JVM: it stops the robot's cycle and
 * runs the program's callback. All methods may be called from any thread.
 */
public class ArKeyHandler implements AutoCloseable {

  /** Up arrow. */
  public static final int UP = 256;

  /** Down arrow. */
  public static final int DOWN = 257;

  /** Left arrow. */
  public static final int LEFT = 258;

  /** Right arrow. */
  public static final int RIGHT = 259;

  /** Escape. */
  public static final int ESCAPE = 260;

  /** Space bar. */
  public static final int SPACE = 261;

  /** Tab. */
  public static final int TAB = 262;

  /** Enter. */
  public static final int ENTER = 263;

  /** Backspace. */
  public static final int BACKSPACE = 264;

  /** F1. */
  public static final int F1 = 266;

  /** F2. */
  public static final int F2 = 267;

  /** F3. */
  public static final int F3 = 268;

  /** F4. */
  public static final int F4 = 269;

  /** F5. */
  public static final int F5 = 270;

  /** F6. */
  public static final int F6 = 271;

  /** F7. */
  public static final int F7 = 272;

  /** F8. */
  public static final int F8 = 273;

  /** F9. */
  public static final int F9 = 274;

  /** F10. */
  public static final int F10 = 275;

  /** F11. */
  public static final int F11 = 276;

  /** F12. */
  public static final int F12 = 277;

  /** Page Up. */
  public static final int PAGEUP = 279;

  /** Page Down. */
  public static final int PAGEDOWN = 280;

  /** Home. */
  public static final int HOME = 281;

  /** End. */
  public static final int END = 282;

  /** Insert. */
  public static final int INSERT = 283;

  /** Delete (forward delete). */
  public static final int DEL = 284;

  /** Name of the sensor-interpretation task added by {@link #attachKeyHandler}. */
  public static final String TASK_NAME = "Key Handler";

  private static final Logger log = LoggerFactory.getLogger(ArKeyHandler.class);
  private static final long READ_TIMEOUT_MS = 50;

  private final Map<Integer, Runnable> handlers = new ConcurrentHashMap<>();
  private final ConcurrentLinkedQueue<Integer> queue = new ConcurrentLinkedQueue<>();
  private final AtomicReference<ArRobot> attached = new AtomicReference<>();
  private final KeySource source;
  private final Thread reader;
  private volatile boolean running;
  private volatile Runnable escapeHandler;

  /** A handler without a reader: keys come only from {@link #feedKey}. */
  public ArKeyHandler() {
    this(null, "ArKeyHandler");
  }

  /**
   * A handler whose reader thread, named {@code threadName}, reads keys from {@code source}; {@link
   * #close()} stops and joins it and closes the source.
   */
  public ArKeyHandler(KeySource source, String threadName) {
    this.source = source;
    if (source == null) {
      reader = null;
      return;
    }
    running = true;
    reader = new Thread(this::readLoop, threadName);
    reader.setDaemon(true);
    reader.start();
  }

  /**
   * A handler reading the terminal this program runs in (switched to raw mode until {@link
   * #close()}).
   *
   * @throws IOException if the terminal cannot be opened
   */
  public static ArKeyHandler forTerminal() throws IOException {
    return new ArKeyHandler(new TerminalKeySource(), "ArKeyHandler-terminal");
  }

  /**
   * Binds {@code key} to {@code handler}.
   *
   * @return false (and changes nothing) if the key already has a handler
   */
  public boolean addKeyHandler(int key, Runnable handler) {
    Objects.requireNonNull(handler, "handler");
    Runnable previous = handlers.putIfAbsent(key, handler);
    if (previous != null) {
      log.info("There is already a handler for key {}", describe(key));
      return false;
    }
    return true;
  }

  /** Unbinds {@code key}; returns whether it had a handler. */
  public boolean remKeyHandler(int key) {
    return handlers.remove(key) != null;
  }

  /** Unbinds every key bound to {@code handler}; returns whether there was one. */
  public boolean remKeyHandler(Runnable handler) {
    return handlers.values().removeIf(h -> h == handler);
  }

  /** The handler bound to {@code key}, or null. */
  public Runnable getKeyHandler(int key) {
    return handlers.get(key);
  }

  /**
   * Queues a key press as if it had been typed (for GUIs and tests). It is handled at the next
   * {@link #checkKeys()}.
   */
  public void feedKey(int key) {
    queue.add(key);
  }

  /** Queues every character of {@code text}, decoded as a terminal would send it. */
  public void feedKeys(CharSequence text) {
    KeySequenceDecoder d = new KeySequenceDecoder(this::feedKey);
    d.accept(text);
    d.timeout();
  }

  /**
   * Takes the next queued key without handling it (ARIA's {@code getKey}).
   *
   * @return the key, or −1 if none is queued
   */
  public int getKey() {
    Integer k = queue.poll();
    return k == null ? -1 : k;
  }

  /**
   * Handles every queued key on the calling thread, in order. A handler that throws is logged; the
   * other keys are still handled.
   */
  public void checkKeys() {
    Integer k;
    while ((k = queue.poll()) != null) {
      Runnable h = handlers.get(k);
      if (h == null) {
        continue;
      }
      try {
        h.run();
      } catch (RuntimeException e) {
        log.error("the handler of key {} threw", describe(k), e);
      }
    }
  }

  /**
   * Attaches to {@code robot} with ARIA's default keys: {@link #checkKeys()} runs every cycle, and
   * Escape stops the robot's cycle.
   */
  public void attachKeyHandler(ArRobot robot) {
    attachKeyHandler(robot, true, null);
  }

  /**
   * Attaches to {@code robot}: {@link #checkKeys()} runs as its sensor-interpretation task "{@value
   * #TASK_NAME}" (position 50), so key handlers run on the cycle thread.
   *
   * @param exitOnEscape bind Escape to stopping the robot's cycle ({@link ArRobot#stopRunning()})
   *     and then running {@code onEscape}
   * @param onEscape what the program does on Escape (e.g. release its main thread), or null; never
   *     System.exit in a library
   */
  public void attachKeyHandler(ArRobot robot, boolean exitOnEscape, Runnable onEscape) {
    Objects.requireNonNull(robot, "robot");
    ArRobot previous = attached.getAndSet(robot);
    if (previous != null && previous != robot) {
      previous.remSensorInterpTask(TASK_NAME);
    }
    robot.addSensorInterpTask(TASK_NAME, 50, this::checkKeys);
    if (exitOnEscape) {
      Runnable h =
          () -> {
            log.info("Escape was pressed, program is exiting.");
            robot.stopRunning();
            if (onEscape != null) {
              onEscape.run();
            }
          };
      Runnable old = escapeHandler;
      if (old != null) {
        handlers.remove(ESCAPE, old);
      }
      escapeHandler = h;
      addKeyHandler(ESCAPE, h);
    }
  }

  /** Detaches from the robot it is attached to (the Escape binding is removed too). */
  public void detach() {
    ArRobot r = attached.getAndSet(null);
    if (r != null) {
      r.remSensorInterpTask(TASK_NAME);
    }
    Runnable h = escapeHandler;
    if (h != null) {
      handlers.remove(ESCAPE, h);
      escapeHandler = null;
    }
  }

  /** The robot this handler is attached to, or null. */
  public ArRobot getAttachedRobot() {
    return attached.get();
  }

  /** Whether the reader thread is running. */
  public boolean isReading() {
    return reader != null && reader.isAlive();
  }

  /**
   * Waits up to {@code timeoutMs} for the reader thread to end (after {@link #close()}, or when its
   * source has ended).
   *
   * @return whether no reader thread is running
   */
  public boolean awaitReaderExit(long timeoutMs) throws InterruptedException {
    if (reader != null) {
      reader.join(Math.max(1, timeoutMs));
    }
    return !isReading();
  }

  /** The reader thread's name, or null without a reader. */
  public String getReaderThreadName() {
    return reader == null ? null : reader.getName();
  }

  private void readLoop() {
    KeySequenceDecoder decoder = new KeySequenceDecoder(this::keyRead);
    try {
      while (running) {
        int c = source.read(READ_TIMEOUT_MS);
        if (c == KeySource.EOF) {
          break;
        }
        if (c == KeySource.TIMEOUT) {
          if (decoder.isPending()) {
            decoder.timeout();
          }
          continue;
        }
        decoder.accept(c);
      }
      decoder.timeout();
    } catch (IOException e) {
      if (running) {
        log.warn("reading keys failed; key handling has stopped: {}", e.toString());
      }
    }
  }

  private void keyRead(int key) {
    queue.add(key);
    if (attached.get() == null) {
      checkKeys();
    }
  }

  /**
   * Stops and joins the reader thread, closes the key source (restoring the terminal) and detaches
   * from the robot. Safe to call more than once.
   */
  @Override
  public void close() {
    running = false;
    detach();
    if (reader == null) {
      return;
    }
    try {
      source.close();
    } catch (IOException e) {
      log.warn("closing the key source failed: {}", e.toString());
    }
    if (Thread.currentThread() != reader) {
      reader.interrupt();
      try {
        reader.join(2000);
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
      if (reader.isAlive()) {
        log.warn("key reader thread {} did not stop within 2 s", reader.getName());
      }
    }
  }

  /** A readable name for a key code. */
  public static String describe(int key) {
    return switch (key) {
      case UP -> "UP";
      case DOWN -> "DOWN";
      case LEFT -> "LEFT";
      case RIGHT -> "RIGHT";
      case ESCAPE -> "ESCAPE";
      case SPACE -> "SPACE";
      case TAB -> "TAB";
      case ENTER -> "ENTER";
      case BACKSPACE -> "BACKSPACE";
      case PAGEUP -> "PAGEUP";
      case PAGEDOWN -> "PAGEDOWN";
      case HOME -> "HOME";
      case END -> "END";
      case INSERT -> "INSERT";
      case DEL -> "DEL";
      default -> {
        if (key >= F1 && key <= F12) {
          yield "F" + (key - F1 + 1);
        }
        yield key >= '!' && key <= '~' ? "'" + (char) key + "'" : Integer.toString(key);
      }
    };
  }
}
