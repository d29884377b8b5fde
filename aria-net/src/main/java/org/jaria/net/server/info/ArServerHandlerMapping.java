package org.jaria.net.server.info;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BiConsumer;
import org.jaria.laser.ArLaserLogger;
import org.jaria.laser.log.ScanLogEntry;
import org.jaria.laser.log.ScanLogHeader;
import org.jaria.net.ArNetPacket;
import org.jaria.net.data.LiveMap;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.PublishedValue;
import org.jaria.net.server.ScanLogName;
import org.jaria.net.server.TextLimits;
import org.jaria.net.server.Where;
import org.jaria.range.ArRangeDevice;
import org.jaria.range.LaserScanSource;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Starting and ending a laser scan log from a client (ArNetworking's {@code
 * ArServerHandlerMapping}, which MobileEyes' "Start scan" used): {@code "mappingStart"} with a file
 * name starts an {@link ArLaserLogger} on the robot's laser, writing {@code name.2d} into the
 * server's map folder; {@code "mappingEnd"} closes it; {@code "mappingStatus"} answers the name
 * being mapped ("" if none) and {@code "mappingStatusBroadcast"} is also sent to the clients that
 * asked for it when a scan starts or ends. Names, layouts and command groups are ARIA's.
 *
 * <p>The file name is confined to the map folder ({@link ScanLogName}); a refused name is answered
 * with ARIA's "could not start" byte followed by a sentence saying why (ARIA's clients read the
 * byte only). Building the map at the end is not this class's job (it needs the mapping module): a
 * program adds it with {@link #addLogEntryCallback} and {@link #addMappingEndedCallback}, as {@code
 * jaria demo guiserver --mapping} does. A scan left running when the server closes is ended by
 * {@link #close()}.
 *
 * <p>The requests run on the server's workers, never on the robot's cycle (opening a file can be
 * slow); the logger then writes on the cycle, as ARIA's does.
 */
public final class ArServerHandlerMapping implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(ArServerHandlerMapping.class);

  /** Answer to mappingStart: the scan started. */
  public static final int STARTED = 0;

  /** Answer to mappingStart: a scan is running already; to mappingEnd: no scan to end. */
  public static final int ALREADY_OR_NONE = 1;

  /** Answer to mappingStart: could not start; to mappingEnd: the log could not be written. */
  public static final int FAILED = 2;

  /** ArNetworking's group of the start and end requests. */
  public static final String GROUP = "Mapping";

  private final ArServerBase server;
  private final ArRobot robot;
  private final Opener opener;
  private final Path folder;
  private final List<Runnable> startCallbacks = new CopyOnWriteArrayList<>();
  private final List<Runnable> begunCallbacks = new CopyOnWriteArrayList<>();
  private final List<Runnable> endCallbacks = new CopyOnWriteArrayList<>();
  private final List<Runnable> endedCallbacks = new CopyOnWriteArrayList<>();
  private final List<BiConsumer<ScanLogHeader, ScanLogEntry>> entryCallbacks =
      new CopyOnWriteArrayList<>();
  private final List<String> startStrings = new CopyOnWriteArrayList<>();
  private final PublishedValue liveMap = new PublishedValue();

  @GuardedBy("this")
  private ArLaserLogger logger;

  @GuardedBy("this")
  private String mapName = "";

  @GuardedBy("this")
  private String fileName = "";

  @GuardedBy("this")
  private Path file;

  /** Makes the logger for an open file (the laser's type stays out of the fields). */
  @FunctionalInterface
  private interface Opener {
    ArLaserLogger open(Writer out, String name);
  }

  /**
   * Registers the mapping requests with {@code server}.
   *
   * @param laser the robot's laser ({@link org.jaria.laser.ArLaser} or {@link
   *     org.jaria.range.ArSimulatedLaser}), already added to the robot
   * @param folder the server's map folder: scans are written there
   * @throws IOException if the folder does not exist
   */
  public <L extends ArRangeDevice & LaserScanSource> ArServerHandlerMapping(
      ArServerBase server, ArRobot robot, L laser, Path folder) throws IOException {
    this.server = Objects.requireNonNull(server, "server");
    this.robot = Objects.requireNonNull(robot, "robot");
    Objects.requireNonNull(laser, "a mapping server needs the robot's laser");
    this.opener = (out, name) -> new ArLaserLogger(robot, laser, 300, 25, out, name);
    this.folder = folder.toRealPath();
    if (!Files.isDirectory(this.folder)) {
      throw new IOException(folder + " is not a folder: give the folder scans are written to");
    }
    server.addData(
        "mappingStart",
        "Starts making a map",
        "string: name of map file",
        "byte: 0 (started mapping), 1 (already mapping), 2 (could not start map); after a 2,"
            + " JAria adds string: why",
        GROUP,
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> start(request.hasMore() ? request.bufToStr() : "", reply));
    server.addData(
        "mappingEnd",
        "Stops making a map",
        "none",
        "byte: 0 (ended mapping), 1 (no mapping to end), 2 (could not move temporary file to"
            + " permanent file); 0 and 2 are sent as ubyte2, as ArNetworking does",
        GROUP,
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> end(reply));
    server.addData(
        "mappingStatus",
        "Gets the status of mapping",
        "none",
        "string: mapName if mapping, empty string if not mapping",
        "RobotInfo",
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> reply.strToBuf(getMapName()));
    server.addData(
        "mappingStatusBroadcast",
        "Gets the status of mapping, also sent when mapping starts or ends (this is a new/better"
            + " mappingStatus)",
        "none",
        "string: mapName if mapping, empty string if not mapping",
        "RobotInfo",
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> reply.strToBuf(getMapName()));
  }

  /**
   * Registers {@code "mappingLiveMap"} (JAria's; {@link LiveMap}): the map growing while a scan
   * runs, as {@link #publishLiveMap} gives it. A monitor subscribes to it at an interval.
   */
  public void addLiveMap() {
    liveMap.publish(LiveMap.NONE);
    server.addPublishedData(
        "mappingLiveMap",
        "the map being built while a scan is logged (JAria)",
        "JAria LiveMap: array of 6 fields: string status; string log file; byte8 scans; points; path; pose",
        "RobotInfo",
        liveMap);
  }

  /** Publishes the map as it grows (from any thread; a builder's, typically). */
  public void publishLiveMap(LiveMap m) {
    liveMap.publish(m);
  }

  private void start(String requested, ArNetPacket reply) {
    String why = startScan(requested);
    if (why == null) {
      reply.byteToBuf(STARTED);
      ArNetPacket b = new ArNetPacket();
      b.strToBuf(getFileName());
      server.broadcastPacketTcp(b, "mappingStatusBroadcast");
    } else if (why.isEmpty()) {
      reply.byteToBuf(ALREADY_OR_NONE);
    } else {
      reply.byteToBuf(FAILED).strToBuf(TextLimits.clip(why, TextLimits.MAX_MESSAGE));
    }
  }

  /**
   * Starts a scan into {@code requested} (the request's rules): null if it started, "" if a scan
   * runs already, else why not. For a program that starts a scan itself.
   */
  public synchronized String startScan(String requested) {
    if (logger != null) {
      log.info("mappingStart: a scan is already being made ({})", fileName);
      return "";
    }
    Path target;
    try {
      target = ScanLogName.resolve(folder, requested);
    } catch (IllegalArgumentException e) {
      log.info("mappingStart: refused '{}': {}", TextLimits.clip(requested, 80), e.getMessage());
      return e.getMessage();
    } catch (IOException e) {
      log.warn("mappingStart: the map folder cannot be read: {}", e.getMessage());
      return "the server's map folder cannot be read (the server's log says why)";
    }
    String name = target.getFileName().toString();
    mapName = requested.toLowerCase(java.util.Locale.ROOT);
    fileName = name;
    file = target;
    startCallbacks.forEach(Runnable::run);
    Writer out;
    try {
      // No link is followed, even one made since the name was checked.
      out =
          Files.newBufferedWriter(
              target,
              StandardCharsets.ISO_8859_1,
              StandardOpenOption.CREATE,
              StandardOpenOption.TRUNCATE_EXISTING,
              StandardOpenOption.WRITE,
              LinkOption.NOFOLLOW_LINKS);
    } catch (IOException | UnsupportedOperationException e) {
      log.warn("mappingStart: cannot write {}: {}", target, e.getMessage());
      clear();
      return "the server cannot write '" + name + "' in its map folder (its log says why)";
    }
    ArLaserLogger l;
    robot.lock();
    try {
      l = opener.open(out, name);
    } finally {
      robot.unlock();
    }
    for (String s : startStrings) {
      l.addInfoToLogPlain(s);
    }
    for (BiConsumer<ScanLogHeader, ScanLogEntry> cb : entryCallbacks) {
      l.addEntryCB(e -> cb.accept(l.getHeader(), e));
    }
    logger = l;
    begunCallbacks.forEach(Runnable::run);
    log.info("mappingStart: scan {} started", name);
    return null;
  }

  private void end(ArNetPacket reply) {
    int r = endScan();
    if (r == ALREADY_OR_NONE) {
      reply.byteToBuf(ALREADY_OR_NONE);
      return;
    }
    // ArNetworking answers a scan ended (or not moved) with two bytes, "no scan" with one.
    reply.uByte2ToBuf(r);
    ArNetPacket b = new ArNetPacket();
    b.strToBuf("");
    server.broadcastPacketTcp(b, "mappingStatusBroadcast");
  }

  /**
   * Ends the scan: {@link #STARTED} (0) if it was written, {@link #ALREADY_OR_NONE} if none runs,
   * {@link #FAILED} if the log could not be written (the server's log says why).
   */
  public synchronized int endScan() {
    if (logger == null) {
      log.info("mappingEnd: no scan is being made");
      return ALREADY_OR_NONE;
    }
    logger.close();
    String failure = logger.getFailure();
    logger = null;
    int r = failure.isEmpty() ? STARTED : FAILED;
    if (!failure.isEmpty()) {
      log.warn("mappingEnd: {}", failure);
    }
    log.info("mappingEnd: scan {} ended", fileName);
    endCallbacks.forEach(Runnable::run);
    endedCallbacks.forEach(Runnable::run);
    clear();
    return r;
  }

  @GuardedBy("this")
  private void clear() {
    mapName = "";
    fileName = "";
    file = null;
  }

  /** Whether a scan is being made. */
  public synchronized boolean isMapping() {
    return logger != null;
  }

  /** Logs the next sweep whether or not the robot moved (ARIA's {@code forceReading}). */
  public synchronized void forceReading() {
    if (logger != null) {
      logger.takeReading();
    }
  }

  /** The log's file name ("lab.2d"), "" when no scan runs. */
  public synchronized String getFileName() {
    return fileName;
  }

  /** The name the client gave, in lower case; "" when no scan runs. */
  public synchronized String getMapName() {
    return mapName;
  }

  /** The log being written (valid in the end callbacks too), or null. */
  public synchronized Path getFile() {
    return file;
  }

  /** The folder scans are written to. */
  public Path getFolder() {
    return folder;
  }

  /** Adds a tag at the robot's pose to the running scan (nothing if none runs). */
  public synchronized void addTagToLog(String text) {
    if (logger != null) {
      logger.addTagToLogPlain(text);
    }
  }

  /** Adds a line without pose to the running scan (nothing if none runs). */
  public synchronized void addInfoToLog(String text) {
    if (logger != null) {
      logger.addInfoToLogPlain(text);
    }
  }

  /** Adds a line written at the start of every scan. */
  public void addStringForStartOfLogs(String s) {
    startStrings.add(s);
  }

  /** Removes a line added with {@link #addStringForStartOfLogs}. */
  public void remStringForStartOfLogs(String s) {
    startStrings.remove(s);
  }

  /** Called when a scan is about to start (its names are set, the file not yet open). */
  public void addMappingStartCallback(Runnable r) {
    startCallbacks.add(r);
  }

  /** Called once a scan has started. */
  public void addMappingBegunCallback(Runnable r) {
    begunCallbacks.add(r);
  }

  /** Called when a scan ends, its log closed ({@link #getFile()} still names it). */
  public void addMappingEndCallback(Runnable r) {
    endCallbacks.add(r);
  }

  /** Called after the end callbacks ({@link #getFile()} still names the log). */
  public void addMappingEndedCallback(Runnable r) {
    endedCallbacks.add(r);
  }

  /**
   * Called with the log's header and every scan and tag of the scans started from now on, right
   * after it is written, on the robot's cycle thread (hand it to another thread: a map builder's
   * queue).
   */
  public void addLogEntryCallback(BiConsumer<ScanLogHeader, ScanLogEntry> cb) {
    entryCallbacks.add(cb);
  }

  /** Ends a scan left running. */
  @Override
  public void close() {
    endScan();
  }
}
