package org.jaria.net.server;

import java.util.List;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.protocol.NetError;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs a server's request handlers where their data says — on a worker, or queued for the robot's
 * cycle with the data's {@link CallPolicy} — turns what they throw into {@code requestFailed}
 * packets, sends their replies, and runs the server's user task on the cycle (queued commands, then
 * the services' cycle tasks). Every request gets a sequence number in arrival order, so that the
 * cycle can tell work asked for before a stop from work asked for after it.
 */
final class CallRunner {

  private static final Logger log = LoggerFactory.getLogger(CallRunner.class);

  /** A task run on every robot cycle. */
  record CycleTask(String name, Runnable task) {}

  /** What a latest-wins or safety request is coalesced by: one client's requests of one data. */
  private record Key(ArServerClient client, int command) {}

  private final ArServerBase server;
  private final CycleQueue cycleQueue;
  private final List<CycleTask> cycleTasks;
  private final AtomicLong lastSeq = new AtomicLong();
  private final AtomicLong escaped = new AtomicLong();

  /** The sequence number of the request whose handler this worker thread runs. */
  private final ThreadLocal<Long> runningSeq =
      ThreadLocal.withInitial(() -> CycleQueue.NOT_A_REQUEST);

  // Only the robot's cycle thread touches it.
  private long cycleFailures;

  CallRunner(ArServerBase server, CycleQueue cycleQueue, List<CycleTask> tasks) {
    this.server = server;
    this.cycleQueue = cycleQueue;
    this.cycleTasks = tasks;
  }

  /** Whether requests of {@code e} are applied on the robot's cycle. */
  boolean onCycle(DataEntry e) {
    return e.publication == null && e.where == Where.CYCLE && server.robotOrNull() != null;
  }

  /**
   * The sequence number for work queued for the cycle now: the request's whose handler runs on this
   * thread, or {@link CycleQueue#NOT_A_REQUEST}.
   */
  long currentRequestSeq() {
    return runningSeq.get();
  }

  /**
   * Queues a request of cycle data {@code e} whose policy is latest-wins or safety: never refused,
   * not counted in the client's pending calls (one client has at most one of each waiting).
   */
  void executeCoalesced(ArServerClient c, DataEntry e, byte[] args, CallPolicy policy) {
    long seq = lastSeq.incrementAndGet();
    CycleQueue.Work w =
        new CycleQueue.Work(
            () -> runCall(c, e, args, null, false, seq),
            () -> sendReply(c, e, null, new ArNetPacket(e.id())),
            () -> reassert(c, e, args));
    Key key = new Key(c, e.id());
    if (policy == CallPolicy.SAFETY) {
      cycleQueue.offerSafety(key, w, seq);
    } else {
      cycleQueue.offerLatest(key, w, seq);
    }
  }

  /** Applies a safety request again after late work, answering nobody. */
  private static void reassert(ArServerClient c, DataEntry e, byte[] args) {
    try {
      e.handler.handle(c, ArNetPacket.wrap(e.id(), args, 0, args.length), new ArNetPacket(e.id()));
    } catch (InterruptedException ex) {
      Thread.currentThread().interrupt();
    } catch (Exception ex) {
      throw new IllegalStateException(e.name() + " could not be applied again: " + ex, ex);
    }
  }

  /**
   * Runs a request of {@code e} where its data says (cycle or worker). {@code r} is the interval
   * request it runs for, or null for a request once. The caller has counted it in the client's
   * pending calls.
   */
  void execute(ArServerClient c, DataEntry e, byte[] args, ArServerClient.Request r) {
    long seq = lastSeq.incrementAndGet();
    Runnable task = () -> runCall(c, e, args, r, true, seq);
    boolean queued;
    if (onCycle(e)) {
      queued = cycleQueue.offer(CycleQueue.Work.of(task), seq);
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

  /**
   * Runs one request and answers it. Nothing escapes: whatever the handler, its reply or the answer
   * to its failure throws is logged (at most once per hundred) and costs only this request.
   */
  private void runCall(
      ArServerClient c,
      DataEntry e,
      byte[] args,
      ArServerClient.Request r,
      boolean counted,
      long seq) {
    try {
      runAndAnswer(c, e, args, r, counted, seq);
    } catch (RuntimeException ex) {
      long n = escaped.incrementAndGet();
      if (n == 1 || n % 100 == 0) {
        log.warn("{} for {} could not be answered (#{})", e.name(), c, n, ex);
      }
    }
  }

  private void runAndAnswer(
      ArServerClient c,
      DataEntry e,
      byte[] args,
      ArServerClient.Request r,
      boolean counted,
      long seq) {
    runningSeq.set(seq);
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
      runningSeq.remove();
      if (counted) {
        c.pendingCalls.decrementAndGet();
      }
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
    // Data whose return description is "none" answer nothing, whatever their flags, as in ARIA
    // (setCameraAbs is RETURN_SINGLE there and sends nothing); a JAria client gets its ack.
    String ret = e.info.returnDescription();
    boolean answers = !e.info.returnsNothing() && !ret.isBlank() && !ret.equalsIgnoreCase("none");
    boolean send = p.getDataLength() > 0 || (r == null && (answers || c.wantsAcks));
    if (send) {
      p.setCommand(e.id());
      server.sendPacket(c, p);
    }
  }

  /** The server's user task on the robot's cycle: queued commands, then the cycle tasks. */
  void cycle() {
    cycleQueue.drain(
        server.getOptions().maxCommandsPerCycle(), r -> runSafely(r, "a queued command"));
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
