package org.jaria.net.server;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.io.IOException;
import java.security.SecureRandom;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;
import org.jaria.net.ArNetPacket;
import org.jaria.net.data.DataInfo;
import org.jaria.net.protocol.NetError;
import org.jaria.net.protocol.Protocol;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The robot program's network server (ArNetworking's {@code ArServerBase}): clients such as a
 * monitor connect over TCP, log in, and then ask for data once, subscribe to published data at a
 * rate, or send commands. Services ({@code ArServerInfoRobot}, {@code ArServerHandlerMap}, the
 * server modes ...) register their data with {@link #addData} and {@link #addPublishedData}.
 *
 * <pre>{@code
 * try (ArServerBase server = new ArServerBase(ServerOptions.builder().port(7272).build(), robot)) {
 *   new ArServerInfoRobot(server, robot);
 *   new ArServerModeStop(server, robot).addAsDefaultMode();
 *   server.open();
 *   robot.waitForRunExit();
 * }
 * }</pre>
 *
 * <p><b>Threads.</b> The robot's cycle is never blocked by the network: the server's user task on
 * the cycle only applies queued commands (at most {@link ServerOptions#maxCommandsPerCycle()}) and
 * runs the services' snapshot tasks, which store immutable records. One I/O thread
 * ("jaria-net-io-PORT") reads and writes every socket without blocking; one publisher thread
 * ("jaria-net-publish-PORT") serves subscriptions; a fixed pool of workers
 * ("jaria-net-worker-PORT-N") runs request handlers. Every queue between them is bounded; {@link
 * #close()} stops and joins every thread.
 *
 * <p><b>Protection.</b> At most {@link ServerOptions#maxClients()} connections; a connection must
 * log in within the login timeout; a packet that is not well-formed closes that connection only; a
 * client that reads too slowly has its subscription updates coalesced (newest wins) and is dropped
 * when its replies exceed {@link ServerOptions#maxQueuedBytes()} or its socket takes nothing for
 * the stall timeout. See {@code aria-net/PROTOCOL.md}.
 */
public class ArServerBase implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(ArServerBase.class);

  /** Name (and position) of the server's user task on the robot's cycle. */
  public static final String USER_TASK = "ArServerBase";

  private static final int USER_TASK_POSITION = 10;

  private final ServerOptions options;
  private final ArRobot robot;
  final ServerStats stats = new ServerStats();
  final SecureRandom random = new SecureRandom();
  private final LoginLimiter loginLimiter;
  private final DataRegistry data = new DataRegistry();
  private final List<ArServerClient> clients = new CopyOnWriteArrayList<>();
  private final List<ServerListener> listeners = new CopyOnWriteArrayList<>();
  private final List<CallRunner.CycleTask> cycleTasks = new CopyOnWriteArrayList<>();
  private final Map<Class<?>, Object> services = new ConcurrentHashMap<>();
  private final CycleQueue cycleQueue;
  private final CallRunner calls;
  private final Dispatcher dispatcher;
  private final Publisher publisher;
  // Written once by open(), read by any thread (getPort() may be asked from another thread than
  // the one that opened): volatile, so that a reader sees them complete.
  private volatile IoLoop io;
  private volatile ThreadPoolExecutor workers;
  private volatile Thread ioThread;
  private volatile Thread publisherThread;
  private volatile boolean open;

  @GuardedBy("this")
  private boolean closed;

  /** A server without a robot (all handlers run on workers). */
  public ArServerBase(ServerOptions options) {
    this(options, null);
  }

  /**
   * A server for {@code robot}: {@link Where#CYCLE} handlers and the services' snapshot tasks run
   * on the robot's cycle.
   */
  public ArServerBase(ServerOptions options, ArRobot robot) {
    this.options = Objects.requireNonNull(options, "options");
    this.robot = robot;
    this.cycleQueue =
        new CycleQueue(options.cycleQueue(), stats.superseded, stats.safetyReasserted);
    this.calls = new CallRunner(this, cycleQueue, cycleTasks);
    this.dispatcher = new Dispatcher(this, options);
    this.publisher = new Publisher(this);
    this.loginLimiter =
        new LoginLimiter(
            options.timeoutClock(),
            options.maxLoginFailures(),
            options.loginFailureWindow().toNanos(),
            options.maxLoginChecksPerSecond());
    register(
        REQUEST_FAILED,
        "JAria: sent to a client whose request could not be carried out (bad arguments, busy,"
            + " failed); ArNetworking clients that do not know it ignore it",
        "none",
        "string: data name; string: why; byte2: JAria's error code",
        "",
        "RETURN_SINGLE",
        Where.WORKER,
        (c, req, rep) -> {},
        null);
  }

  /** Name of the data JAria sends to a client whose request failed (see PROTOCOL.md). */
  public static final String REQUEST_FAILED = "requestFailed";

  LoginLimiter loginLimiter() {
    return loginLimiter;
  }

  // ------------------------------------------------------------------ lifecycle

  /**
   * Starts listening and serving.
   *
   * @throws IOException if the port cannot be opened (the message says what to do)
   * @throws IllegalStateException if already opened or closed
   */
  public synchronized void open() throws IOException {
    if (open || closed) {
      throw new IllegalStateException("a server can be opened once; make a new one");
    }
    refuseOpenBeyondLoopback();
    io = new IoLoop(this, options, dispatcher);
    int port = io.port();
    AtomicInteger n = new AtomicInteger();
    workers =
        new ThreadPoolExecutor(
            options.workerThreads(),
            options.workerThreads(),
            0,
            TimeUnit.MILLISECONDS,
            new ArrayBlockingQueue<>(options.workerQueue()),
            r -> {
              Thread t = new Thread(r, "jaria-net-worker-" + port + "-" + n.incrementAndGet());
              t.setDaemon(true);
              // Handlers' failures are answered to their client (CallRunner); this only says so
              // should something else ever end a worker.
              t.setUncaughtExceptionHandler(
                  (th, ex) -> log.error("{} ended by {}", th.getName(), ex.toString(), ex));
              return t;
            });
    ioThread = new Thread(io, "jaria-net-io-" + port);
    ioThread.setDaemon(true);
    publisherThread = new Thread(publisher, "jaria-net-publish-" + port);
    publisherThread.setDaemon(true);
    open = true;
    if (robot != null) {
      robot.addUserTask(USER_TASK, USER_TASK_POSITION, calls::cycle);
    }
    ioThread.start();
    publisherThread.start();
    log.info(
        "server '{}' speaking ArNetworking on {}:{} (tcp{}; {})",
        options.serverName(),
        io.address(),
        port,
        io.udpPort() > 0 ? ", udp " + io.udpPort() : " only",
        options.authenticator().isOpen() ? "no login needed" : "login required");
    if (options.authenticator().isOpen() && !io.isLoopbackOnly()) {
      log.warn(
          "no login needed and listening on {}: anybody who can reach port {} may use every"
              + " service of this server",
          io.address(),
          port);
    }
    if (!options.authenticator().isOpen() && !io.isLoopbackOnly()) {
      log.warn(
          "ArNetworking's login sends an MD5 digest of the password over a plain connection,"
              + " which anyone on the network can capture and attack offline: listen on the"
              + " loopback address (reach it through an SSH tunnel) or trust the network");
    }
  }

  /**
   * A server that drives a robot and asks for no login must not listen beyond the loopback address
   * unless told so: anybody who can reach the port could drive the robot.
   */
  private void refuseOpenBeyondLoopback() throws IOException {
    String bind = options.bindAddress();
    if (robot == null
        || !options.authenticator().isOpen()
        || options.openBeyondLoopback()
        || bind == null) {
      return;
    }
    if (!java.net.InetAddress.getByName(bind).isLoopbackAddress()) {
      throw new IllegalStateException(
          "a server without a login listening on "
              + bind
              + " would let anybody who can reach port "
              + options.port()
              + " drive the robot: give users and passwords (an Authenticator), listen on"
              + " 127.0.0.1, or set openBeyondLoopback if that is really meant");
    }
  }

  /** The address the server listens on ("127.0.0.1", "0.0.0.0" for every interface ...). */
  public String getAddress() {
    IoLoop l = io;
    if (l == null) {
      throw new IllegalStateException("the server is not open yet; call open() first");
    }
    return l.address();
  }

  /** Whether the server is open. */
  public boolean isOpen() {
    return open;
  }

  /** The port the server listens on (useful with port 0). */
  public int getPort() {
    IoLoop l = io;
    if (l == null) {
      throw new IllegalStateException("the server is not open yet; call open() first");
    }
    return l.port();
  }

  /**
   * Closes every connection (telling logged-in clients the server is shutting down), removes the
   * user task and stops and joins every thread. Safe to call more than once.
   */
  @Override
  public void close() {
    synchronized (this) {
      if (closed) {
        return;
      }
      closed = true;
      if (!open) {
        return;
      }
      open = false;
    }
    if (robot != null) {
      robot.remUserTask(USER_TASK);
    }
    publisher.stop();
    io.stop();
    workers.shutdown();
    join(publisherThread);
    join(ioThread);
    try {
      if (!workers.awaitTermination(5, TimeUnit.SECONDS)) {
        workers.shutdownNow();
        log.warn("a request handler did not finish within 5 s of closing; interrupted it");
        workers.awaitTermination(5, TimeUnit.SECONDS);
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
    cycleQueue.clear();
    log.info("server '{}' closed ({})", options.serverName(), stats);
  }

  private static void join(Thread t) {
    try {
      t.join(TimeUnit.SECONDS.toMillis(5));
      if (t.isAlive()) {
        log.warn("thread {} did not stop within 5 s", t.getName());
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  // ------------------------------------------------------------------ data

  /**
   * Registers a request (ArNetworking's {@code addData}): clients call it by name with arguments
   * and get one reply.
   *
   * @param name unique name clients use
   * @param description what it does, for people
   * @param argumentDescription the arguments in order, e.g. "double x, double y" ("none")
   * @param returnDescription the reply in order ("none" for a command)
   * @param commandGroup the group a user needs ("" for anybody)
   * @param where where the handler runs
   * @return the entry as clients see it
   * @throws IllegalArgumentException if the name is taken
   */
  public DataInfo addData(
      String name,
      String description,
      String argumentDescription,
      String returnDescription,
      String commandGroup,
      Where where,
      RequestHandler handler) {
    return addData(
        name,
        description,
        argumentDescription,
        returnDescription,
        commandGroup,
        isNone(returnDescription) ? "RETURN_NONE" : "RETURN_SINGLE",
        where,
        handler);
  }

  /**
   * As {@link #addData(String, String, String, String, String, Where, RequestHandler)}, with
   * ArNetworking's data flags ("RETURN_NONE", "RETURN_SINGLE", "RETURN_VIDEO" ... joined by '|').
   * The reply the handler writes is sent unless the flags say RETURN_NONE and it is empty.
   */
  public DataInfo addData(
      String name,
      String description,
      String argumentDescription,
      String returnDescription,
      String commandGroup,
      String dataFlags,
      Where where,
      RequestHandler handler) {
    Objects.requireNonNull(handler, "handler");
    Objects.requireNonNull(where, "where");
    return register(
        name,
        description,
        argumentDescription,
        returnDescription,
        commandGroup,
        dataFlags,
        where,
        handler,
        null);
  }

  private static boolean isNone(String d) {
    return d == null || d.isBlank() || d.equalsIgnoreCase("none");
  }

  /**
   * Registers published data: clients subscribe to it at a rate (or ask for it once) and receive
   * the publication's latest value, encoded once per version for all of them.
   *
   * @return the entry as clients see it
   * @throws IllegalArgumentException if the name is taken
   */
  public DataInfo addPublishedData(
      String name,
      String description,
      String returnDescription,
      String commandGroup,
      Publication publication) {
    Objects.requireNonNull(publication, "publication");
    return register(
        name,
        description,
        "none",
        returnDescription,
        commandGroup,
        "RETURN_SINGLE",
        Where.WORKER,
        null,
        publication);
  }

  private DataInfo register(
      String name,
      String description,
      String argDesc,
      String retDesc,
      String group,
      String flags,
      Where where,
      RequestHandler handler,
      Publication publication) {
    return data.register(
        name, description, argDesc, retDesc, group, flags, where, handler, publication);
  }

  /** Every registered data, in registration order. */
  public List<DataInfo> dataList() {
    return data.dataList();
  }

  /** Whether data of this name is registered (ArNetworking's {@code dataExists}). */
  public boolean dataExists(String name) {
    return data.byName(name) != null;
  }

  DataEntry entry(int command) {
    return data.entry(command);
  }

  /**
   * Sets how requests of data {@code name} wait for the robot's cycle (JAria's addition; see {@link
   * CallPolicy}): {@code "stop"} is {@link CallPolicy#SAFETY}, {@code "ratioDrive"} {@link
   * CallPolicy#LATEST_WINS}. It matters for data whose handler runs on the cycle; for data run on a
   * worker, SAFETY only lifts the limit of waiting requests.
   *
   * @throws IllegalArgumentException if there is no data of that name
   */
  public void setCallPolicy(String name, CallPolicy policy) {
    DataEntry e = data.byName(name);
    if (e == null) {
      throw new IllegalArgumentException(
          "no data '" + name + "' to set a call policy for: register it first");
    }
    e.policy = Objects.requireNonNull(policy, "policy");
  }

  /**
   * How requests of data {@code name} wait ({@link CallPolicy#QUEUED} if there is no such data).
   */
  public CallPolicy getCallPolicy(String name) {
    DataEntry e = data.byName(name);
    return e == null ? CallPolicy.QUEUED : e.policy;
  }

  /** The command number of data {@code name}, or 0 if there is none. */
  public int findCommandFromName(String name) {
    DataEntry e = data.byName(name);
    return e == null ? 0 : e.id();
  }

  // ------------------------------------------------------------------ the robot's cycle

  /** The robot the server serves, or null. */
  public ArRobot getRobot() {
    return robot;
  }

  /**
   * Runs {@code task} on the robot's cycle (from the server's user task), or at once on a server
   * without a robot.
   *
   * @return false if the cycle's queue is full (the task is not run)
   */
  public boolean runOnCycle(Runnable task) {
    if (robot == null) {
      task.run();
      return true;
    }
    // Work a request's handler queues carries that request's place in line (see CallPolicy).
    return cycleQueue.offer(CycleQueue.Work.of(task), calls.currentRequestSeq());
  }

  /**
   * Commands waiting for the robot's next cycle (requests of {@link Where#CYCLE} data and work that
   * services queued with {@link #runOnCycle}). A lockstep test advances the simulation while this
   * is not zero, so a command is applied at once without letting virtual time run freely.
   */
  public int getPendingCycleCommands() {
    return cycleQueue.size();
  }

  /**
   * Adds (or replaces, by name) a task run on every robot cycle inside the server's user task,
   * after queued commands: services use it to snapshot state and modes to do their work. Tasks must
   * be quick and must not block.
   */
  public void addCycleTask(String name, Runnable task) {
    remCycleTask(name);
    cycleTasks.add(new CallRunner.CycleTask(name, task));
  }

  /** Removes a cycle task by name. */
  public void remCycleTask(String name) {
    cycleTasks.removeIf(t -> t.name().equals(name));
  }

  /**
   * A per-server helper object shared by services (for example the registry of server modes), made
   * with {@code create} the first time.
   */
  public <T> T getService(Class<T> type, Supplier<T> create) {
    return type.cast(services.computeIfAbsent(type, k -> create.get()));
  }

  // ------------------------------------------------------------------ clients

  /** The connected clients (including those still logging in). */
  public List<ArServerClient> getClients() {
    return List.copyOf(clients);
  }

  /** Number of logged-in clients. */
  public int getNumClients() {
    int n = 0;
    for (ArServerClient c : clients) {
      if (c.isLoggedIn()) {
        n++;
      }
    }
    return n;
  }

  /** Counters of connections, refusals and drops. */
  public ServerStats getStats() {
    return stats;
  }

  /** Adds a listener for clients logging in and leaving. */
  public void addListener(ServerListener l) {
    listeners.add(l);
  }

  /** Removes a listener. */
  public void removeListener(ServerListener l) {
    listeners.remove(l);
  }

  /** The options the server was made with. */
  public ServerOptions getOptions() {
    return options;
  }

  List<ArServerClient> clientsSnapshot() {
    return clients;
  }

  void addClient(ArServerClient c) {
    clients.add(c);
  }

  void removeClient(ArServerClient c, String reason) {
    clients.remove(c);
    for (ServerListener l : listeners) {
      try {
        l.clientClosed(c, reason);
      } catch (RuntimeException e) {
        log.warn("a server listener failed", e);
      }
    }
  }

  void clientLoggedIn(ArServerClient c) {
    for (ServerListener l : listeners) {
      try {
        l.clientLoggedIn(c);
      } catch (RuntimeException e) {
        log.warn("a server listener failed", e);
      }
    }
  }

  IoLoop io() {
    return io;
  }

  ThreadPoolExecutor workers() {
    return workers;
  }

  ArRobot robotOrNull() {
    return robot;
  }

  Publisher publisher() {
    return publisher;
  }

  // ------------------------------------------------------------------ sending

  /** Queues packet {@code p} (its command set) for {@code c}. */
  void sendPacket(ArServerClient c, ArNetPacket p) {
    enqueue(c, Outgoing.frame(p.toWire()), !onIoThread());
  }

  /** Tells {@code c} that its request of {@code e} failed (JAria's requestFailed packet). */
  void requestFailed(ArServerClient c, DataEntry e, NetError code, String message) {
    stats.requestErrors.increment();
    // The message may quote what the client sent: cut it, so the packet always fits.
    String why = TextLimits.clip(message, TextLimits.MAX_MESSAGE);
    log.debug("{}: {} failed ({}): {}", c, e.name(), code, why);
    ArNetPacket p = new ArNetPacket(Protocol.FIRST_DATA_COMMAND);
    p.strToBuf(e.name()).strToBuf(why).byte2ToBuf(code.code());
    sendPacket(c, p);
  }

  /**
   * Sends {@code packet} to every logged-in client that has requested data {@code name} (at an
   * interval or with -1, "when it changes"): ArNetworking's {@code broadcastPacketTcp}. The
   * packet's command is set to the data's number.
   *
   * @return false if there is no such data
   */
  public boolean broadcastPacketTcp(ArNetPacket packet, String name) {
    return broadcastPacketTcpWithExclusion(packet, name, null);
  }

  /**
   * As {@link #broadcastPacketTcp}, to every such client but {@code excluded} (ArNetworking's name;
   * for example the client whose change the broadcast announces).
   */
  public boolean broadcastPacketTcpWithExclusion(
      ArNetPacket packet, String name, ArServerClient excluded) {
    DataEntry e = data.byName(name);
    if (e == null) {
      return false;
    }
    packet.setCommand(e.id());
    byte[] wire = null;
    for (ArServerClient c : clients) {
      if (c != excluded && c.isLoggedIn() && c.requests.containsKey(e.id())) {
        if (wire == null) {
          wire = packet.toWire();
        }
        enqueue(c, Outgoing.frame(wire), true);
      }
    }
    return true;
  }

  /** As {@link #broadcastPacketTcp}: JAria sends every packet over TCP (see PROTOCOL.md). */
  public boolean broadcastPacketUdp(ArNetPacket packet, String name) {
    return broadcastPacketTcp(packet, name);
  }

  boolean onIoThread() {
    return Thread.currentThread() == ioThread;
  }

  void enqueue(ArServerClient c, Outgoing o, boolean wakeup) {
    if (c.isClosed()) {
      return;
    }
    if (!c.out.offer(o)) {
      // The close happens on the I/O thread; replies refused meanwhile must not count again.
      if (c.dropRequested.compareAndSet(false, true)) {
        stats.droppedSlow.increment();
        log.info(
            "{} reads too slowly: more than {} bytes of replies waiting; dropping it",
            c,
            options.maxQueuedBytes());
        io.requestClose(
            c,
            NetError.TOO_SLOW,
            "more than " + options.maxQueuedBytes() + " bytes of replies waiting: read faster");
      }
      return;
    }
    io.scheduleWrite(c, wakeup);
  }

  /**
   * Runs a request of {@code e} where its data says (cycle or worker); see {@link CallRunner}. The
   * caller has counted it in the client's pending calls.
   */
  void execute(ArServerClient c, DataEntry e, byte[] args, ArServerClient.Request r) {
    calls.execute(c, e, args, r);
  }

  /** Runs a latest-wins or safety request of cycle data (not counted in pending calls). */
  void executeCoalesced(ArServerClient c, DataEntry e, byte[] args, CallPolicy policy) {
    calls.executeCoalesced(c, e, args, policy);
  }

  /** Whether requests of {@code e} are applied on the robot's cycle. */
  boolean onCycle(DataEntry e) {
    return calls.onCycle(e);
  }

  /** The UDP port (0 if none is open). */
  int udpPort() {
    IoLoop l = io;
    return l == null ? 0 : l.udpPort();
  }
}
