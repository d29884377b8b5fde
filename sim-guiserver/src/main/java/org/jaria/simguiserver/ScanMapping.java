package org.jaria.simguiserver;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Locale;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.jaria.laser.log.LoggedScan;
import org.jaria.laser.log.ScanLogEntry;
import org.jaria.laser.log.ScanLogHeader;
import org.jaria.mapping.BuiltMap;
import org.jaria.mapping.LogMapping;
import org.jaria.mapping.MapBuildException;
import org.jaria.mapping.MapBuilder;
import org.jaria.mapping.MapBuilderParams;
import org.jaria.mapping.MapSnapshot;
import org.jaria.net.data.ArDrawingData;
import org.jaria.net.data.LiveMap;
import org.jaria.net.server.ScanLogName;
import org.jaria.net.server.info.ArServerHandlerMapping;
import org.jaria.net.server.info.ArServerInfoDrawings;
import org.jaria.range.ArSimulatedLaser;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Mapping while driving, on a guiServer: the server's mapping services ({@link
 * ArServerHandlerMapping}) plus a map builder fed with each scan as it is logged, on a thread of
 * its own ({@code jaria-scan-mapping}; never on the robot's cycle), which publishes the growing map
 * to monitors ({@code mappingLiveMap}) and, when the client ends the scan, writes the built map
 * beside the log in the map folder ({@code lab.2d} gives {@code lab.map}, or {@code lab-2.map} if
 * that exists), where clients can switch to it (ARIA's {@code Files/Map}). {@link #addDrawing} also
 * offers the growing map as an ArNetworking drawing ({@value #DRAWING}), which MobileEyes-era
 * clients and {@code jaria monitor} draw without knowing anything of mapping.
 *
 * <p>The robot's cycle only offers each entry to a queue; if the builder falls more than {@link
 * #MAX_QUEUED} entries behind, entries are dropped (counted) and the map is built again from the
 * log file at the end.
 */
public final class ScanMapping implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(ScanMapping.class);

  /** Entries the builder may be behind before the cycle drops them. */
  public static final int MAX_QUEUED = 20_000;

  /** The drawing of the growing map. */
  public static final String DRAWING = "mappingMap";

  /** How the growing map is drawn: dark green dots, under the sonar, asked for every second. */
  static final ArDrawingData DRAWING_DATA =
      new ArDrawingData(
          "polyDots", ArDrawingData.color(0x1B, 0x7F, 0x3B), 40, 62, 1000, 0, "DefaultOn");

  /** The live map is published every this many scans. */
  static final int PUBLISH_EVERY = 5;

  private final ArServerHandlerMapping handler;
  private final BlockingQueue<Object> queue = new LinkedBlockingQueue<>();
  private final AtomicInteger queued = new AtomicInteger();
  private final AtomicLong dropped = new AtomicLong();
  private final Consumer<String> report;
  private final Thread worker;
  private volatile String status = "no scan";
  private volatile LiveMap latest = LiveMap.NONE;
  private volatile Path lastMap;
  private final AtomicInteger built = new AtomicInteger();

  private record Begin(String fileName) {}

  private record Entry(ScanLogHeader header, ScanLogEntry entry) {}

  private record End(Path log) {}

  private record Stop() {}

  /**
   * Mapping services on {@code handler}'s server, building each scan's map.
   *
   * @param report told each status change ("built lab.map: ..."), e.g. printed on the terminal
   */
  public ScanMapping(ArServerHandlerMapping handler, Consumer<String> report) {
    this.handler = handler;
    this.report = report;
    handler.addLiveMap();
    // Queued before the logger starts, so no entry of the new scan can come before it.
    handler.addMappingStartCallback(() -> put(new Begin(handler.getFileName())));
    handler.addLogEntryCallback(this::offer);
    handler.addMappingEndedCallback(() -> put(new End(handler.getFile())));
    worker = new Thread(this::run, "jaria-scan-mapping");
    worker.setDaemon(true);
    worker.start();
  }

  /**
   * The mapping services on a robot whose laser is the simulator's (the embedded simulator, {@code
   * jaria sim}, MobileSim): adds an {@link ArSimulatedLaser} to the robot.
   *
   * @param folder the server's map folder, where scans and maps are written
   * @throws IOException if the folder does not exist
   */
  public static ScanMapping withSimulatedLaser(
      org.jaria.net.guiserver.GuiServer gui, ArRobot robot, Path folder, Consumer<String> report)
      throws IOException {
    ArSimulatedLaser laser = new ArSimulatedLaser();
    robot.lock();
    try {
      robot.addRangeDevice(laser);
    } finally {
      robot.unlock();
    }
    ScanMapping m =
        new ScanMapping(new ArServerHandlerMapping(gui.getServer(), robot, laser, folder), report);
    m.addDrawing(gui.getDrawings());
    return m;
  }

  /**
   * Offers the growing map (and, after a scan, the map built) as drawing {@value #DRAWING}.
   *
   * @return false if the server has a drawing of that name already
   */
  public boolean addDrawing(ArServerInfoDrawings drawings) {
    return drawings.addDrawing(DRAWING_DATA, DRAWING, () -> latest.points());
  }

  /** The mapping services. */
  public ArServerHandlerMapping handler() {
    return handler;
  }

  /** What it is doing, for people. */
  public String status() {
    return status;
  }

  /** The last map built, or null. */
  public Path lastMap() {
    return lastMap;
  }

  /** How many maps were built. */
  public int mapsBuilt() {
    return built.get();
  }

  /** Entries dropped because the builder was behind. */
  public long dropped() {
    return dropped.get();
  }

  /** On the robot's cycle: hand the entry on, never wait. */
  private void offer(ScanLogHeader header, ScanLogEntry e) {
    if (header == null || queued.get() >= MAX_QUEUED) {
      dropped.incrementAndGet();
      return;
    }
    queued.incrementAndGet();
    queue.add(new Entry(header, e));
  }

  private void put(Object o) {
    queue.add(o);
  }

  private void run() {
    MapBuilder builder = null;
    String fileName = "";
    long scans = 0;
    long droppedAtBegin = 0;
    try {
      while (true) {
        Object o = queue.take();
        if (o instanceof Stop) {
          return;
        } else if (o instanceof Begin b) {
          builder = null;
          fileName = b.fileName();
          scans = 0;
          droppedAtBegin = dropped.get();
          setStatus("scanning " + fileName, fileName, 0, null);
        } else if (o instanceof Entry en) {
          queued.decrementAndGet();
          if (builder == null) {
            builder = new MapBuilder(en.header(), MapBuilderParams.DEFAULTS);
          }
          builder.add(en.entry());
          if (en.entry() instanceof LoggedScan && ++scans % PUBLISH_EVERY == 0) {
            setStatus("scanning " + fileName, fileName, scans, builder.snapshot());
          }
        } else if (o instanceof End end && end.log() != null) {
          buildAtEnd(builder, end.log(), dropped.get() > droppedAtBegin);
          builder = null;
        }
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  /** Writes the scan's map: from the live builder, or from the log if entries were dropped. */
  private void buildAtEnd(MapBuilder builder, Path logFile, boolean incomplete) {
    String name = logFile.getFileName().toString();
    setStatus("building the map of " + name, name, 0, builder == null ? null : builder.snapshot());
    try {
      BuiltMap m;
      if (incomplete || builder == null) {
        m = LogMapping.build(logFile, MapBuilderParams.DEFAULTS, p -> {}).map();
      } else {
        m = builder.finish();
      }
      Path target = ScanLogName.mapFor(logFile);
      Path tmp = target.resolveSibling(target.getFileName() + ".part");
      m.writeFile(tmp);
      Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE);
      lastMap = target;
      int[] xy = new int[2 * m.pointCount()];
      for (int i = 0; i < m.pointCount(); i++) {
        xy[2 * i] = m.x(i);
        xy[2 * i + 1] = m.y(i);
      }
      String s =
          String.format(
              Locale.ROOT,
              "built %s from %s: %d points, %d lines",
              target.getFileName(),
              name,
              m.pointCount(),
              m.lines().size());
      // The built map stays drawn (thinned) until the next scan starts.
      publish(LiveMap.of(s, name, 0, xy, new int[0], null));
      report.accept(s);
      built.incrementAndGet();
    } catch (MapBuildException | org.jaria.laser.log.ScanLogFormatException e) {
      setStatus(name + ": no map: " + e.getMessage(), name, 0, null);
    } catch (IOException | RuntimeException e) {
      log.warn("building the map of {} failed", logFile, e);
      setStatus(name + ": no map: " + e.getMessage(), name, 0, null);
    }
  }

  private void publish(LiveMap m) {
    status = m.status();
    latest = m;
    handler.publishLiveMap(m);
  }

  private void setStatus(String s, String fileName, long scans, MapSnapshot snap) {
    if (snap == null) {
      publish(LiveMap.of(s, fileName, scans, new int[0], new int[0], null));
    } else {
      int[] xy = new int[snap.size() * 2];
      for (int i = 0; i < snap.size(); i++) {
        xy[2 * i] = snap.x(i);
        xy[2 * i + 1] = snap.y(i);
      }
      int[] path = new int[snap.pathSize() * 2];
      for (int i = 0; i < snap.pathSize(); i++) {
        path[2 * i] = (int) Math.round(snap.pathX(i));
        path[2 * i + 1] = (int) Math.round(snap.pathY(i));
      }
      publish(LiveMap.of(s, fileName, scans, xy, path, snap.pose()));
    }
    if (scans == 0) {
      report.accept(s);
    }
  }

  /** Ends a scan left running (building its map), then stops the builder's thread. */
  @Override
  public void close() {
    handler.close();
    queue.add(new Stop());
    try {
      worker.join();
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }
}
