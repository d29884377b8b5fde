package org.jaria.mapping;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.laser.log.LogTag;
import org.jaria.laser.log.LoggedScan;
import org.jaria.laser.log.ScanLogEntry;
import org.jaria.laser.log.ScanLogHeader;

/**
 * Builds a map from laser scans one at a time, as a log is read or while the robot drives: each
 * scan is matched against the scans of the last metres (scan-to-map matching from the odometry's
 * guess), becomes a pose of a pose graph, and is checked against places seen long before (loop
 * closure, {@link LoopCloser}); at the end the graph is optimised and {@link #finish()} writes the
 * map in the log's own frame (the first logged pose stays where the log says).
 *
 * <pre>{@code
 * MapBuilder b = new MapBuilder(reader.header(), MapBuilderParams.DEFAULTS);
 * for (ScanLogEntry e = reader.next(); e != null; e = reader.next()) {
 *   b.add(e);
 * }
 * BuiltMap map = b.finish();
 * map.writeFile(Path.of("lab.map"));
 * }</pre>
 *
 * <p>{@link #progress()} and {@link #snapshot()} show the map growing (a progress bar, a live map
 * in a monitor). Memory grows with the area mapped, not with the log's length: once a pose leaves
 * the local window and an older pose shows the same place, its scan is let go; what it saw is kept
 * as map cells in the older pose's frame (moving with it), each cell once.
 *
 * <p>Not thread-safe: one thread adds scans; another thread that wants progress or a snapshot must
 * synchronise with it (or ask between scans).
 */
public final class MapBuilder {

  /** A scan with fewer match points than this is not matched (its pose comes from odometry). */
  static final int MIN_MATCH_POINTS = 10;

  /** A match from the guess this good (share of overlapping points on a surface) is kept. */
  static final double GOOD_FIT = 0.85;

  /** Less translation than this since the last pose is a turn on the spot, mm. */
  static final double SPOT_MM = 40;

  /** The robot counts as having moved once it is this far from its first pose, mm. */
  static final double MOVED_MM = 100;

  /** ... or turned this far, degrees. */
  static final double TURNED_DEG = 5;

  private static final boolean DEBUG = Boolean.getBoolean("jaria.mapping.debug");
  private final ScanLogHeader header;
  private final MapBuilderParams params;
  private final NoEchoFilter noEcho = new NoEchoFilter();
  private final Nodes nodes;
  private final Trajectory.Builder trajectory = new Trajectory.Builder();
  private final PointIndex local = new PointIndex();
  private final IcpMatcher icp = new IcpMatcher();
  private final CorrelativeSearch nearby = CorrelativeSearch.narrow();
  private final LoopCloser loops;
  private final List<LogTag> tags = new ArrayList<>();
  private final List<int[]> tagNodes = new ArrayList<>();
  private final List<ArPose> tagOffsets = new ArrayList<>();
  private ArPose firstOdometry;
  private ArPose lastOdometry;
  private ArPose lastEstimate;
  private double travel;
  private double maxMoved;
  private double maxTurned;
  private int pruneCursor;
  private long scansRead;
  private long scansUsed;
  private long stationary;
  private long sparse;
  private long matchFailures;
  private long pruned;
  private boolean matched;
  private long searches;
  private long timeMatch;
  private long timeLoops;
  private long timeLocal;

  /** A builder for scans of a log with {@code header} (the laser's mounting and view). */
  public MapBuilder(ScanLogHeader header, MapBuilderParams params) {
    this.header = Objects.requireNonNull(header, "header");
    this.params = Objects.requireNonNull(params, "params");
    this.loops = new LoopCloser(params);
    this.nodes = new Nodes(params.resolutionMm());
  }

  /** Adds a scan or a tag of the log. */
  public void add(ScanLogEntry e) {
    if (e instanceof LoggedScan s) {
      addScan(s);
    } else if (e instanceof LogTag t) {
      addTag(t);
    }
  }

  /** Adds a tag: a goal placed while logging becomes a goal of the map. */
  public void addTag(LogTag t) {
    if (nodes.size() == 0 || !t.isCairn()) {
      return;
    }
    int n = nodes.size() - 1;
    tags.add(t);
    tagNodes.add(new int[] {n});
    tagOffsets.add(Poses.between(nodes.odometry(n), t.robotPose()));
  }

  /** Adds a scan. */
  public void addScan(LoggedScan s) {
    scansRead++;
    ArPose odo = s.robotPose();
    ScanPoints pts = ScanPoints.of(s, header.laserPose(), params, noEcho);
    if (firstOdometry == null) {
      firstOdometry = odo;
    }
    maxMoved = Math.max(maxMoved, odo.findDistanceTo(firstOdometry));
    maxTurned = Math.max(maxTurned, Math.abs(ArMath.subAngle(odo.th(), firstOdometry.th())));
    if (nodes.size() == 0) {
      if (pts.matchCount < MIN_MATCH_POINTS) {
        sparse++;
        return;
      }
      int n = nodes.add(odo, odo, 0, s.time(), pts);
      trajectory.add(s.id(), s.time(), odo, n, ArPose.ORIGIN);
      lastOdometry = odo;
      lastEstimate = odo;
      scansUsed++;
      return;
    }
    ArPose guess = Poses.compose(lastEstimate, Poses.between(lastOdometry, odo));
    int last = nodes.size() - 1;
    ArPose lastNodeOdo = nodes.odometry(last);
    double moved = lastNodeOdo.findDistanceTo(odo);
    double turned = Math.abs(ArMath.subAngle(lastNodeOdo.th(), odo.th()));
    travel += lastOdometry.findDistanceTo(odo);
    lastOdometry = odo;
    if (moved < params.nodeSpacingMm() && turned < params.nodeTurnDeg()) {
      stationary++;
      lastEstimate = guess;
      trajectory.add(s.id(), s.time(), odo, last, Poses.between(nodes.estimate(last), guess));
      return;
    }
    if (pts.matchCount < MIN_MATCH_POINTS) {
      sparse++;
      lastEstimate = guess;
      trajectory.add(s.id(), s.time(), odo, last, Poses.between(nodes.estimate(last), guess));
      return;
    }
    long t0 = System.nanoTime();
    ArPose est = match(guess, pts, moved, turned);
    timeMatch += System.nanoTime() - t0;
    int n = nodes.add(est, odo, travel, s.time(), pts);
    ArPose rel = Poses.between(nodes.estimate(last), est);
    // ICP pins what the scan sees (across a corridor, the heading); along a featureless
    // corridor it knows nothing, and there the odometry's guess is what the estimate rests on.
    double[] info =
        matched
            ? plus(toGraphInfo(icp.info, est.th()), odometryInfo(moved, turned))
            : odometryInfo(moved, turned);
    nodes.graph.addEdge(last, n, rel.x(), rel.y(), rel.th(), info, false);
    trajectory.add(s.id(), s.time(), odo, n, ArPose.ORIGIN);
    scansUsed++;
    long t1 = System.nanoTime();
    loops.tryClose(nodes, n, pts);
    timeLoops += System.nanoTime() - t1;
    lastEstimate = nodes.estimate(n);
    prune(n);
  }

  /**
   * Matches the scan against the local map; the guess itself if the match is not convincing. The
   * guess (odometry since the last pose) errs in proportion to the distance and the turn since
   * then: a robot turning on the spot does not move, and odometry knows that well, so the search
   * window and the pull towards the guess follow the motion.
   */
  private ArPose match(ArPose guess, ScanPoints pts, double moved, double turned) {
    // Turning on the spot: the wheels' error moves the robot by millimetres at most, while the
    // view swings past doorways whose sides alone would place it; keep the position.
    boolean spot = moved < SPOT_MM;
    local.clear();
    int newest = nodes.size() - 1;
    double from = nodes.travel(newest) - params.localWindowMm();
    for (int k = newest; k >= 0 && nodes.travel(k) >= from; k--) {
      nodes.addPoints(k, local);
    }
    long tl = System.nanoTime();
    local.build();
    timeLocal += System.nanoTime() - tl;
    icp.setPrior(spot ? 5 : 30 + 0.1 * moved, 1 + 0.1 * turned);
    icp.match(local, pts.kx, pts.ky, pts.matchCount, guess.x(), guess.y(), guess.th());
    if (icp.overlapInliers < GOOD_FIT || icp.inlierFraction < 0.5) {
      // a poor fit from the guess: search around it for a better start
      nearby.search(
          local,
          pts.kx,
          pts.ky,
          pts.matchCount,
          guess.x(),
          guess.y(),
          guess.th(),
          spot ? 10 : 40 + 0.3 * moved,
          2 + 0.15 * turned);
      icp.match(local, pts.kx, pts.ky, pts.matchCount, nearby.x, nearby.y, nearby.thDeg);
      searches++;
    }
    ArPose est = new ArPose(icp.x, icp.y, icp.thDeg);
    if (icp.inlierFraction < 0.3
        || icp.pairs < MIN_MATCH_POINTS
        || est.findDistanceTo(guess) > 1000
        || Math.abs(ArMath.subAngle(est.th(), guess.th())) > 30) {
      matchFailures++;
      matched = false;
      return guess;
    }
    matched = true;
    return est;
  }

  /**
   * Lets go of the scans of poses that left the local window and repeat an older pose; their map
   * points are kept in that older pose's frame.
   */
  private void prune(int newest) {
    if (!params.pruneRedundant()) {
      return;
    }
    double windowStart = nodes.travel(newest) - params.localWindowMm();
    for (; pruneCursor < newest && nodes.travel(pruneCursor) < windowStart; pruneCursor++) {
      int k = pruneCursor;
      double oldest = nodes.travel(k) - params.loopMinTravelMm();
      ArPose pk = nodes.estimate(k);
      for (int j = 0; j < k && nodes.travel(j) <= oldest; j++) {
        if (nodes.points(j) != null
            && nodes.distanceSq(j, k) < 200 * 200
            && Math.abs(ArMath.subAngle(nodes.graph.thDeg(j), pk.th())) < 15) {
          nodes.foldPoints(k, j);
          pruned++;
          break;
        }
      }
    }
  }

  /**
   * ICP information (mm, rad, the map's axes) in the graph's units (m, rad) and in the frame of the
   * matched pose (heading {@code thDeg}), where the graph measures an edge's error, with a floor
   * against degeneracy. A corridor's walls pin the pose across the corridor, not along it: the
   * graph must know which of its axes that is, whichever way the corridor runs.
   */
  static double[] toGraphInfo(double[] mmInfo, double thDeg) {
    double c = Math.cos(Math.toRadians(thDeg));
    double s = Math.sin(Math.toRadians(thDeg));
    double a = mmInfo[0];
    double b = mmInfo[1];
    double d = mmInfo[3];
    double xt = mmInfo[2];
    double yt = mmInfo[4];
    // R' I R, R the rotation by the pose's heading
    double[] g = {
      (c * c * a + 2 * c * s * b + s * s * d) * 1e6,
      (-c * s * a + (c * c - s * s) * b + c * s * d) * 1e6,
      (c * xt + s * yt) * 1e3,
      (s * s * a - 2 * c * s * b + c * c * d) * 1e6,
      (-s * xt + c * yt) * 1e3,
      mmInfo[5]
    };
    g[0] += 1;
    g[3] += 1;
    g[5] += 1;
    return g;
  }

  private static double[] plus(double[] a, double[] b) {
    double[] out = new double[6];
    for (int k = 0; k < 6; k++) {
      out[k] = a[k] + b[k];
    }
    return out;
  }

  /**
   * Information of odometry between two poses: 5 % of the distance (at least 10 mm); the heading to
   * a quarter of a degree, half a degree a metre and 5 % of the turn (wheels keep a straight line
   * well; it is in turns that they slip).
   */
  private static double[] odometryInfo(double movedMm, double turnedDeg) {
    double sxy = Math.max(0.01, 0.05 * movedMm / 1000);
    double sth = Math.toRadians(0.25 + 0.5 * movedMm / 1000 + 0.05 * turnedDeg);
    return new double[] {1 / (sxy * sxy), 0, 0, 1 / (sxy * sxy), 0, 1 / (sth * sth)};
  }

  /** How far the build has come ({@code fraction} -1: the builder does not know the log's size). */
  public BuildProgress progress() {
    return progress(-1);
  }

  /** How far the build has come, with the share of the log read. */
  public BuildProgress progress(double fraction) {
    return new BuildProgress(
        scansRead,
        scansUsed,
        nodes.size(),
        loops.closures(),
        lastEstimate == null ? ArPose.ORIGIN : lastEstimate,
        fraction);
  }

  /** The map so far, for drawing while the robot drives (points at 50 mm, the path). */
  public MapSnapshot snapshot() {
    return MapAssembler.snapshot(nodes);
  }

  /** Bytes of scan points held (the part of the memory that grows with the map). */
  public long pointBytes() {
    return nodes.pointBytes();
  }

  /** Poses in the graph, and how many still hold points. */
  public int poseCount() {
    return nodes.size();
  }

  /** Poses whose points are still held. */
  public int posesWithPoints() {
    return nodes.withPoints();
  }

  /**
   * Optimises the whole graph and assembles the map: points thinned to the resolution, lines fitted
   * to the walls, the robot's start as RobotHome, goals logged on the way.
   *
   * @throws MapBuildException if the log had no usable laser scans or the robot never moved
   */
  public BuiltMap finish() throws MapBuildException {
    if (scansRead == 0) {
      throw new MapBuildException(
          "the log has no laser scans (no scan1: or sick1: lines): log with a laser connected"
              + " (jaria laser log, or sickLogger with -connectLaser)");
    }
    if (nodes.size() == 0) {
      throw new MapBuildException(
          "no scan of the log has enough laser readings ("
              + scansRead
              + " scans, each fewer than "
              + MIN_MATCH_POINTS
              + " usable points): is the laser's view blocked, or every reading beyond "
              + (int) params.matchRangeMm()
              + " mm?");
    }
    if (maxMoved < MOVED_MM && maxTurned < TURNED_DEG) {
      throw new MapBuildException(
          "the robot never moved while logging ("
              + scansRead
              + (scansRead == 1 ? " scan" : " scans")
              + ", all within "
              + (int) MOVED_MM
              + " mm and "
              + (int) TURNED_DEG
              + " degrees of the first): drive it around the building with the laser on");
    }
    if (DEBUG) {
      System.out.printf(
          "match %.0f ms (local index %.0f ms, %d searches), loops %.0f ms%n",
          timeMatch / 1e6, timeLocal / 1e6, searches, timeLoops / 1e6);
      System.out.println(loops.timing() + ", " + nodes.size() + " poses");
    }
    loops.optimize(nodes);
    return MapAssembler.assemble(
        nodes,
        trajectory.build(nodes),
        params,
        tags,
        tagNodes,
        tagOffsets,
        new BuiltMap.Stats(
            scansRead,
            scansUsed,
            stationary,
            sparse,
            matchFailures,
            nodes.size(),
            loops.closures(),
            loops.rejected() + loops.dropped(),
            loops.optimizations(),
            pruned,
            noEcho.dropped(),
            noEcho.noEchoRange()));
  }
}
