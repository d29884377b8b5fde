package org.jaria.apps.mapper;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;
import javafx.application.Platform;
import org.jaria.apps.fx.BackgroundWork;
import org.jaria.apps.fx.PointLayer;
import org.jaria.geom.ArPose;
import org.jaria.laser.log.LoggedScan;
import org.jaria.laser.log.ScanLogEntry;
import org.jaria.laser.log.ScanLogFormatException;
import org.jaria.laser.log.ScanLogReader;
import org.jaria.map.ArMapPoints;
import org.jaria.mapping.BuiltMap;
import org.jaria.mapping.LogMapping;
import org.jaria.mapping.MapBuildException;
import org.jaria.mapping.MapBuilderParams;
import org.jaria.mapping.Trajectory;

/**
 * Opening a laser scan log ({@code .2d}) in the map editor: the map is built on the editor's worker
 * thread with the status bar's progress bar following the log, then shown as a new, unsaved map
 * (Save asks where), with every reading of the log placed by the corrected path drawn faintly under
 * it, so one sees what the builder kept. Editing goes on as with any map.
 */
final class ScanLogOpener {

  /** The raw readings are thinned to one per cell of this size, mm. */
  static final int RAW_CELL_MM = 20;

  private ScanLogOpener() {}

  /** Whether {@code file} is a scan log by its name. */
  static boolean isScanLog(Path file) {
    return file.getFileName() != null
        && file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".2d");
  }

  /** What the worker hands back: the map as a document, its points' index and the raw readings. */
  private record Built(
      MapDocument doc,
      PointLayer layer,
      PointLayer raw,
      List<MapProblem> problems,
      String summary) {}

  /** Builds {@code log} on {@code w}'s worker and shows it. */
  static void open(MapperWindow w, Path log) {
    w.status("Building a map from " + log);
    BackgroundWork work = w.work();
    String name = log.getFileName().toString();
    work.submit(
        "Building " + name,
        () -> {
          LogMapping.Result r =
              LogMapping.build(
                  log,
                  MapBuilderParams.DEFAULTS,
                  p -> {
                    double f = p.fraction();
                    Platform.runLater(() -> work.progressProperty().set(f));
                  });
          BuiltMap m = r.map();
          AtomicLong ids = new AtomicLong(1);
          MapFile.Loaded l = MapFile.wrap(m.toArMap(), ids::getAndIncrement);
          String title = name.substring(0, name.length() - 3) + ".map";
          MapDocument d = new MapDocument(l, null, ids, title);
          ArMapPoints p = l.content().points();
          PointLayer layer = new PointLayer(p.xArray(), p.yArray());
          int[][] raw = rawReadings(log, m.trajectory());
          String summary =
              String.format(
                  Locale.ROOT,
                  "Built %s from %s: %d points, %d lines, %d scans; the log's readings are drawn"
                      + " under it (Save asks where to write the map)",
                  title,
                  name,
                  p.size(),
                  l.content().lines().size(),
                  m.trajectory().size());
          return new Built(
              d,
              layer,
              new PointLayer(raw[0], raw[1]),
              new MapValidator().validate(l.content(), layer),
              summary);
        },
        b -> {
          w.setDocument(b.doc(), b.layer(), b.problems());
          w.view().setUnderlay(b.raw());
          w.view().fit();
          w.status(b.summary());
          w.ready().complete(null);
        },
        e -> {
          w.prompts().error("Cannot build a map from " + name, openError(log, e));
          w.ready().completeExceptionally(e);
        });
  }

  static String openError(Path log, Exception e) {
    if (e instanceof ScanLogFormatException || e instanceof MapBuildException) {
      return e.getMessage()
          + "\n\nThe log cannot be built into a map. Check that it was written by a robot with a"
          + " laser that moved (jaria laser log, sickLogger).";
    }
    return MapperWindow.openError(log, e);
  }

  /**
   * Every reading with an echo of the scans on {@code path}, placed by their corrected poses and
   * thinned to one per {@link #RAW_CELL_MM} cell: x values, then y values.
   */
  static int[][] rawReadings(Path log, Trajectory path) throws IOException {
    int[] ids = new int[path.size()];
    for (int i = 0; i < ids.length; i++) {
      ids[i] = path.scanId(i);
    }
    long[] keys = new long[4096];
    int n = 0;
    try (ScanLogReader r = ScanLogReader.open(log)) {
      ArPose mount = r.header().laserPose();
      for (ScanLogEntry e = r.next(); e != null; e = r.next()) {
        if (!(e instanceof LoggedScan s)) {
          continue;
        }
        int k = indexOf(ids, s.id());
        if (k < 0) {
          continue;
        }
        ArPose robot = path.pose(k);
        double rc = Math.cos(robot.getThRad());
        double rs = Math.sin(robot.getThRad());
        double lx = robot.x() + rc * mount.x() - rs * mount.y();
        double ly = robot.y() + rs * mount.x() + rc * mount.y();
        double lt = Math.toRadians(robot.th() + mount.th());
        double c = Math.cos(lt);
        double sn = Math.sin(lt);
        for (int i = 0; i < s.size(); i++) {
          if (!s.hasEcho(i)) {
            continue;
          }
          double gx = lx + c * s.x(i) - sn * s.y(i);
          double gy = ly + sn * s.x(i) + c * s.y(i);
          if (n == keys.length) {
            keys = Arrays.copyOf(keys, n * 2);
          }
          keys[n++] =
              key(Math.floorDiv((long) gx, RAW_CELL_MM), Math.floorDiv((long) gy, RAW_CELL_MM));
        }
      }
    }
    Arrays.sort(keys, 0, n);
    int[] xs = new int[n];
    int[] ys = new int[n];
    int m = 0;
    for (int i = 0; i < n; i++) {
      if (i > 0 && keys[i] == keys[i - 1]) {
        continue;
      }
      xs[m] = (int) (keys[i] >> 32) * RAW_CELL_MM + RAW_CELL_MM / 2;
      ys[m] = (int) keys[i] * RAW_CELL_MM + RAW_CELL_MM / 2;
      m++;
    }
    return new int[][] {Arrays.copyOf(xs, m), Arrays.copyOf(ys, m)};
  }

  private static long key(long cx, long cy) {
    return (cx << 32) | (cy & 0xFFFFFFFFL);
  }

  /** Where {@code id} is in {@code ids} (sorted as the log numbers its scans), or -1. */
  private static int indexOf(int[] ids, int id) {
    int i = Arrays.binarySearch(ids, id);
    if (i >= 0) {
      return i;
    }
    for (int k = 0; k < ids.length; k++) {
      if (ids[k] == id) {
        return k; // a log whose numbers are not in order
      }
    }
    return -1;
  }
}
