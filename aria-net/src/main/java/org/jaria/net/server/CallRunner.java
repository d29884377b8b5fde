package org.jaria.net.server;

import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.RejectedExecutionException;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.protocol.NetError;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs a server's request handlers where their data says — on a worker, or queued for the robot's
 * cycle — turns what they throw into {@code requestFailed} packets, sends their replies, and runs
 * the server's user task on the cycle (queued commands, then the services' cycle tasks).
 */
final class CallRunner {

  private static final Logger log = LoggerFactory.getLogger(CallRunner.class);

  /** A task run on every robot cycle. */
  record CycleTask(String name, Runnable task) {}

  private final ArServerBase server;
  private final ArrayBlockingQueue<Runnable> cycleQueue;
  private final List<CycleTask> cycleTasks;
  // Only the robot's cycle thread touches it.
  private long cycleFailures;

  CallRunner(ArServerBase server, ArrayBlockingQueue<Runnable> cycleQueue, List<CycleTask> tasks) {
    this.server = server;
    this.cycleQueue = cycleQueue;
    this.cycleTasks = tasks;
  }

  /**
   * Runs a request of {@code e} where its data says (cycle or worker). {@code r} is the interval
   * request it runs for, or null for a request once. The caller has counted it in the client's
   * pending calls.
   */
  void execute(ArServerClient c, DataEntry e, byte[] args, ArServerClient.Request r) {
    Runnable task = () -> runCall(c, e, args, r);
    boolean queued;
    if (e.publication == null && e.where == Where.CYCLE && server.robotOrNull() != null) {
      queued = cycleQueue.offer(task);
    } else {
      try {
        server.workers().execute(task);
        queued = true;
      } catch (RejectedExecutionException ex) {
        queued = false;
      }
    }
    if (!queued) {
      c.pendingCalls.decrementAndGet();
      if (r != null) {
        r.running.set(false);
      }
      server.stats.busy.increment();
      server.requestFailed(c, e, NetError.BUSY, "the server is busy; try again in a moment");
    }
  }

  private void runCall(ArServerClient c, DataEntry e, byte[] args, ArServerClient.Request r) {
    try {
      if (c.isClosed()) {
        return;
      }
      if (e.publication != null) {
        DataEntry.Encoded enc = e.currentEncoded();
        if (enc == null) {
          server.requestFailed(c, e, NetError.UNAVAILABLE, e.name() + " has no value yet");
        } else {
          server.enqueue(c, Outgoing.update(-1, enc.version(), enc.wire()), !server.onIoThread());
        }
        return;
      }
      ArNetPacket reply = new ArNetPacket(e.id());
      if (e.where == Where.WORKER) {
        // One client's handlers run one at a time, as in ArNetworking's single server loop, so
        // the packets of a multi-packet answer (getMap) never interleave with another's.
        synchronized (c.handlerLock) {
          e.handler.handle(c, ArNetPacket.wrap(e.id(), args, 0, args.length), reply);
          sendReply(c, e, r, reply);
        }
      } else {
        e.handler.handle(c, ArNetPacket.wrap(e.id(), args, 0, args.length), reply);
        sendReply(c, e, r, reply);
      }
    } catch (ArNetPacketException ex) {
      server.requestFailed(c, e, NetError.BAD_ARGUMENTS, e.name() + ": " + ex.getMessage());
    } catch (NetRequestException ex) {
      server.requestFailed(c, e, ex.getCode(), ex.getMessage());
    } catch (InterruptedException ex) {
      Thread.currentThread().interrupt();
      server.requestFailed(c, e, NetError.FAILED, e.name() + " was interrupted");
    } catch (Exception ex) {
      log.warn("{} failed for {}", e.name(), c, ex);
      server.requestFailed(c, e, NetError.FAILED, e.name() + " failed: " + ex);
    } finally {
      c.pendingCalls.decrementAndGet();
      if (r != null) {
        r.running.set(false);
      }
    }
  }

  /**
   * Sends a handler's reply: always when it holds something; an empty one to a request once unless
   * the data returns nothing (then only to a JAria client, as its acknowledgement); never an empty
   * one for a request at an interval (an ArNetworking handler that sends nothing sends nothing).
   */
  private void sendReply(ArServerClient c, DataEntry e, ArServerClient.Request r, ArNetPacket p) {
    boolean send =
        p.getDataLength() > 0 || (r == null && (!e.info.returnsNothing() || c.wantsAcks));
    if (send) {
      p.setCommand(e.id());
      server.sendPacket(c, p);
    }
  }

  /** The server's user task on the robot's cycle: queued commands, then the cycle tasks. */
  void cycle() {
    int max = server.getOptions().maxCommandsPerCycle();
    Runnable r;
    for (int i = 0; i < max && (r = cycleQueue.poll()) != null; i++) {
      runSafely(r, "a queued command");
    }
    for (CycleTask t : cycleTasks) {
      runSafely(t.task(), t.name());
    }
  }

  private void runSafely(Runnable r, String what) {
    try {
      r.run();
    } catch (RuntimeException e) {
      if (++cycleFailures == 1 || cycleFailures % 100 == 0) {
        log.warn("{} failed on the robot's cycle (#{})", what, cycleFailures, e);
      }
    }
  }
}
