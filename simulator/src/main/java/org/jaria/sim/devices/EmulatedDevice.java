package org.jaria.sim.devices;

import java.io.IOException;
import java.util.concurrent.TimeUnit;
import org.jaria.connection.ArDeviceConnection;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * An emulated device on one connection (a pty end or an accepted TCP socket), run by a thread of
 * its own: it reads requests, answers them, and between requests does its periodic work (a laser
 * sends scans). The faults of {@link DeviceFaults} are applied to what it sends.
 */
public abstract class EmulatedDevice implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(EmulatedDevice.class);

  /** The connection the device talks on. */
  protected final ArDeviceConnection connection;

  /** The faults it shows. */
  protected final DeviceFaults faults;

  private final Thread thread;
  private volatile boolean running = true;
  private volatile boolean unplugged;
  private long sentBytes;

  /**
   * A device on {@code connection} (opened by {@link #start}).
   *
   * @param threadName the name of its thread
   */
  protected EmulatedDevice(ArDeviceConnection connection, DeviceFaults faults, String threadName) {
    this.connection = connection;
    this.faults = faults;
    this.thread = new Thread(this::loop, threadName);
    this.thread.setDaemon(true);
  }

  /** Opens the connection (if needed) and starts answering. */
  public void start() throws IOException {
    if (connection.getStatus() != ArDeviceConnection.Status.OPEN) {
      connection.open();
    }
    thread.start();
  }

  private void loop() {
    byte[] buf = new byte[4096];
    try {
      while (running) {
        long wait = Math.max(1, millisToNextTick());
        int n = connection.read(buf, 0, buf.length, wait);
        if (n < 0) {
          break;
        }
        if (n > 0) {
          received(buf, n);
        }
        if (running && millisToNextTick() <= 0) {
          tick();
        }
      }
    } catch (IOException e) {
      if (running) {
        log.debug("{}: connection ended: {}", thread.getName(), e.getMessage());
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } finally {
      running = false;
      connection.close();
    }
  }

  /** Handles {@code n} received bytes. */
  protected abstract void received(byte[] b, int n) throws IOException, InterruptedException;

  /** Milliseconds until {@link #tick()} is due (large if nothing periodic is going on). */
  protected abstract long millisToNextTick();

  /** Periodic work, such as sending a scan. */
  protected abstract void tick() throws IOException;

  /** Waits the configured answer delay (a slow device), then sends {@code b}. */
  protected void answer(byte[] b) throws IOException, InterruptedException {
    if (faults.answerDelayMs() > 0) {
      connection.clock().sleepNanos(TimeUnit.MILLISECONDS.toNanos(faults.answerDelayMs()));
    }
    send(b, b.length);
  }

  /** Sends {@code len} bytes of {@code b}, losing every n-th byte if the faults say so. */
  protected void send(byte[] b, int len) throws IOException {
    int every = faults.dropEveryNthByte();
    if (every <= 0) {
      connection.write(b, 0, len);
      sentBytes += len;
      return;
    }
    byte[] out = new byte[len];
    int k = 0;
    for (int i = 0; i < len; i++) {
      sentBytes++;
      if (sentBytes % every != 0) {
        out[k++] = b[i];
      }
    }
    connection.write(out, 0, k);
  }

  /**
   * Sends the first half of {@code b}, then closes the connection and stops: the cable was pulled
   * mid-telegram.
   */
  protected void unplugMidway(byte[] b) throws IOException {
    send(b, b.length / 2);
    unplugged = true;
    running = false;
    connection.close();
  }

  /** Whether the device was "unplugged" by its faults. */
  public boolean wasUnplugged() {
    return unplugged;
  }

  /** Whether the device's thread is still answering. */
  public boolean isRunning() {
    return running && thread.isAlive();
  }

  /** Waits for the device's thread to end (after an unplug, or after {@link #close()}). */
  public boolean join(long timeoutMs) throws InterruptedException {
    thread.join(timeoutMs);
    return !thread.isAlive();
  }

  /** Stops answering and closes the connection. */
  @Override
  public void close() {
    running = false;
    connection.close();
    try {
      thread.join(2000);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }
}
