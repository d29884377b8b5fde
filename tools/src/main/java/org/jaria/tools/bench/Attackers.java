package org.jaria.tools.bench;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.SocketChannel;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Hostile connections for the benchmarks, on one thread: {@code n} connections to a port that never
 * send a valid packet (silent, or one garbage byte a second each) and connect again as soon as the
 * server drops them, for as long as they run. Stopped and joined by {@link #close()}.
 */
public final class Attackers implements AutoCloseable {

  private static final byte[] GARBAGE = {'x'};

  private final int port;
  private final boolean trickle;
  private final SocketChannel[] socks;
  private final Thread thread;
  private final CountDownLatch connected = new CountDownLatch(1);
  private final AtomicLong reconnects = new AtomicLong();
  private volatile boolean running = true;

  /**
   * Starts {@code n} attackers on the loopback {@code port}; with {@code trickle}, each sends one
   * garbage byte a second, else nothing.
   */
  public Attackers(int port, int n, boolean trickle) {
    this.port = port;
    this.trickle = trickle;
    this.socks = new SocketChannel[n];
    this.thread = new Thread(this::run, "bench-attackers-" + port);
    thread.setDaemon(true);
    thread.start();
  }

  /** Waits until every attacker has connected once (at most 30 s). */
  public void awaitConnected() throws InterruptedException {
    connected.await(30, TimeUnit.SECONDS);
  }

  /** Connections made again after the server dropped one. */
  public long reconnects() {
    return reconnects.get();
  }

  private void run() {
    ByteBuffer buf = ByteBuffer.allocate(4096);
    long nextByte = System.nanoTime();
    try {
      for (int i = 0; i < socks.length && running; i++) {
        socks[i] = open();
      }
      connected.countDown();
      while (running) {
        boolean send = trickle && System.nanoTime() - nextByte >= 0;
        if (send) {
          nextByte += TimeUnit.SECONDS.toNanos(1);
        }
        for (int i = 0; i < socks.length && running; i++) {
          if (!alive(socks[i], buf, send)) {
            close(socks[i]);
            socks[i] = open();
            reconnects.incrementAndGet();
          }
        }
        Thread.sleep(2); // an attacker's pace, not a synchronisation
      }
    } catch (IOException e) {
      // the server's port closed: the attack is over
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } finally {
      connected.countDown();
      for (SocketChannel c : socks) {
        close(c);
      }
    }
  }

  /** Reads what the server sent (and sends a garbage byte); false once the server dropped it. */
  private static boolean alive(SocketChannel c, ByteBuffer buf, boolean send) {
    try {
      buf.clear();
      if (c.read(buf) < 0) {
        return false;
      }
      if (send) {
        c.write(ByteBuffer.wrap(GARBAGE));
      }
      return true;
    } catch (IOException reset) {
      return false;
    }
  }

  private SocketChannel open() throws IOException {
    SocketChannel c = SocketChannel.open();
    c.socket().connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 10_000);
    c.configureBlocking(false);
    return c;
  }

  private static void close(SocketChannel c) {
    if (c != null) {
      try {
        c.close();
      } catch (IOException ignored) {
        // closing anyway
      }
    }
  }

  @Override
  public void close() {
    running = false;
    thread.interrupt();
    boolean interrupted = false;
    while (thread.isAlive()) {
      try {
        thread.join();
      } catch (InterruptedException e) {
        interrupted = true;
      }
    }
    if (interrupted) {
      Thread.currentThread().interrupt();
    }
  }
}
