package org.jaria.action;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.range.LaserScan;
import org.jaria.range.LaserScanSource;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Drives up to a triangular target seen by a laser, such as a docking station (ARIA's {@code
 * ArActionTriangleDriveTo}). Lines are found in the laser's scans ({@link ArLineFinder}), the
 * target's vertex among them ({@link TriangleFinder}; by default two 254 mm sides at 135°), and the
 * robot drives first to an approach point (1000 mm out from the vertex along its bisector), turns
 * to face the vertex, then drives to the final point (400 mm out) and aligns with it. With {@link
 * #setGotoVertex(boolean)} it drives at the vertex instead, until the final distance is reached (or
 * a bumper stops it).
 *
 * <p>The action does nothing until {@link #activate()} is called (it starts inactive-in-state even
 * though, like every action, it is "active" when added). If the vertex is not seen for the
 * vertex-unseen time (4 s), it fails, or with {@link #setAcquire(boolean)} turns in place at the
 * acquire turn speed to look for it. The vertex is remembered in odometry coordinates, so it stays
 * put on the floor when localization corrects the robot's pose.
 *
 * <p>The laser is anything that gives {@link LaserScan}s ({@link LaserScanSource}). Without one,
 * activating fails at once.
 */
public class ArActionTriangleDriveTo extends ArAction {

  /** What the action is doing. */
  public enum State {
    /** Not trying. */
    STATE_INACTIVE,
    /** Looking for the target. */
    STATE_ACQUIRE,
    /** Turning in place to find the target. */
    STATE_SEARCHING,
    /** Driving to the approach point. */
    STATE_GOTO_APPROACH,
    /** Facing the target from the approach point. */
    STATE_ALIGN_APPROACH,
    /** Driving at the vertex. */
    STATE_GOTO_VERTEX,
    /** Driving to the final point. */
    STATE_GOTO_FINAL,
    /** Facing the target from the final point. */
    STATE_ALIGN_FINAL,
    /** At the target, facing it. */
    STATE_SUCCEEDED,
    /** The target was lost (or there is no laser). */
    STATE_FAILED
  }

  private static final Logger log = LoggerFactory.getLogger(ArActionTriangleDriveTo.class);

  private final ArActionDesired desired = new ArActionDesired();
  private final TriangleFinder finder = new TriangleFinder();
  private ArLineFinder lineFinder = new ArLineFinder();
  private LaserScanSource laser;
  private double finalDistFromVertex;
  private double approachDistFromVertex;
  private double speed;
  private double closeDist;
  private double acquireTurnSpeed;
  private boolean acquire;
  private boolean gotoVertex;
  private boolean adjustVertex;
  private double ignoreTriangleDist = 250;
  private boolean useIgnoreInGoto;
  private int vertexUnseenStopMSecs = 4000;
  private double maxDistBetweenLinePoints;
  private int localXOffset;
  private int localYOffset;
  private double thOffset;
  private State state = State.STATE_INACTIVE;
  private ArPose vertex = ArPose.ORIGIN;
  private boolean vertexSeen;
  private long vertexSeenLastNanos;
  private double originalAngle = Double.NaN;
  private long linesCounter = -1;
  private List<ArLineFinderSegment> lines = List.of();
  private LaserScan linesScan;

  /**
   * "triangleDriveTo" with ARIA's defaults; the laser is the robot's (the first range device that
   * gives laser scans) unless one is set with {@link #setLaserScanSource}.
   */
  public ArActionTriangleDriveTo() {
    this("triangleDriveTo", null);
  }

  /**
   * ARIA's constructor: the laser is the robot's (the first of its range devices that gives laser
   * scans, found when the action starts) unless one is set with {@link #setLaserScanSource}.
   */
  public ArActionTriangleDriveTo(
      String name,
      double finalDistFromVertex,
      double approachDistFromVertex,
      double speed,
      double closeDist,
      double acquireTurnSpeed) {
    this(
        name,
        null,
        finalDistFromVertex,
        approachDistFromVertex,
        speed,
        closeDist,
        acquireTurnSpeed);
  }

  /** ARIA's defaults (final 400 mm, approach 1000 mm, 200 mm/s, close 100 mm, 30 deg/s). */
  public ArActionTriangleDriveTo(String name, LaserScanSource laser) {
    this(name, laser, 400, 1000, 200, 100, 30);
  }

  /**
   * A triangle drive-to action.
   *
   * @param name the action's name
   * @param laser where scans come from (may be set later)
   * @param finalDistFromVertex distance from the vertex to stop at, mm
   * @param approachDistFromVertex distance of the approach point from the vertex, mm (0: none)
   * @param speed top speed, mm/s
   * @param closeDist how close to a point counts as there, mm
   * @param acquireTurnSpeed rotational velocity while searching, deg/s
   */
  public ArActionTriangleDriveTo(
      String name,
      LaserScanSource laser,
      double finalDistFromVertex,
      double approachDistFromVertex,
      double speed,
      double closeDist,
      double acquireTurnSpeed) {
    super(name, "Finds a triangle and drives in front of it");
    this.laser = laser;
    setParameters(finalDistFromVertex, approachDistFromVertex, speed, closeDist, acquireTurnSpeed);
  }

  /** Sets the parameters as the constructor does. */
  public void setParameters(
      double finalDistFromVertex,
      double approachDistFromVertex,
      double speed,
      double closeDist,
      double acquireTurnSpeed) {
    locked(
        () -> {
          this.finalDistFromVertex = finalDistFromVertex;
          this.approachDistFromVertex = approachDistFromVertex;
          this.speed = speed;
          this.closeDist = closeDist;
          this.acquireTurnSpeed = acquireTurnSpeed;
        });
  }

  /** Sets where laser scans come from. */
  public void setLaserScanSource(LaserScanSource source) {
    locked(() -> this.laser = source);
  }

  /** Sets the line finder (to tune its tolerances). */
  public void setLineFinder(ArLineFinder finder) {
    locked(() -> this.lineFinder = finder);
  }

  /** The line finder used. */
  public ArLineFinder getLineFinder() {
    return lockedGet(() -> lineFinder);
  }

  /** Sets the target's shape (ARIA's defaults: 254, 135, 254). */
  public void setTriangleParams(double line1Length, double angleBetween, double line2Length) {
    locked(() -> finder.setTriangleParams(line1Length, angleBetween, line2Length));
  }

  /** Sets whether to turn in place looking for a target not seen (default false: fail). */
  public void setAcquire(boolean acquire) {
    locked(() -> this.acquire = acquire);
  }

  /** Whether it turns in place looking for the target. */
  public boolean getAcquire() {
    return lockedGet(() -> acquire);
  }

  /** Sets the final distance from the vertex, mm. */
  public void setFinalDistFromVertex(double dist) {
    locked(() -> finalDistFromVertex = dist);
  }

  /** The final distance from the vertex, mm. */
  public double getFinalDistFromVertex() {
    return lockedGet(() -> finalDistFromVertex);
  }

  /** Sets whether to drive at the vertex itself rather than the final point. */
  public void setGotoVertex(boolean gotoVertex) {
    locked(() -> this.gotoVertex = gotoVertex);
  }

  /** Whether it drives at the vertex itself. */
  public boolean getGotoVertex() {
    return lockedGet(() -> gotoVertex);
  }

  /** Sets whether the vertex is moved to the closest laser reading near it (default false). */
  public void setAdjustVertex(boolean adjustVertex) {
    locked(() -> this.adjustVertex = adjustVertex);
  }

  /** Whether the vertex is adjusted to the closest laser reading. */
  public boolean getAdjustVertex() {
    return lockedGet(() -> adjustVertex);
  }

  /**
   * Sets the distance from the final point within which the target is no longer looked for (its
   * sides are too close to see well), mm (default 250), and whether that applies when driving at
   * the vertex too.
   */
  public void setIgnoreTriangleDist(double dist, boolean useIgnoreInGotoVertexMode) {
    locked(
        () -> {
          ignoreTriangleDist = dist;
          useIgnoreInGoto = useIgnoreInGotoVertexMode;
        });
  }

  /** The distance within which the target is no longer looked for, mm. */
  public double getIgnoreTriangleDist() {
    return lockedGet(() -> ignoreTriangleDist);
  }

  /** Sets how long to carry on without seeing the vertex, ms (default 4000). */
  public void setVertexUnseenStopMSecs(int ms) {
    locked(() -> vertexUnseenStopMSecs = ms);
  }

  /** How long it carries on without seeing the vertex, ms. */
  public int getVertexUnseenStopMSecs() {
    return lockedGet(() -> vertexUnseenStopMSecs);
  }

  /** Sets the largest gap between points of one line, mm (0: the line finder's default). */
  public void setMaxDistBetweenLinePoints(int mm) {
    locked(() -> maxDistBetweenLinePoints = mm);
  }

  /** Ignores targets farther than this from the robot's line of travel, mm (0: no limit). */
  public void setMaxLateralDist(int mm) {
    locked(() -> finder.setMaxLateralDist(mm));
  }

  /** Ignores targets misaligned with the robot by more than this, degrees (0: no limit). */
  public void setMaxAngleMisalignment(int degrees) {
    locked(() -> finder.setMaxAngleMisalignment(degrees));
  }

  /**
   * Shifts the vertex used: by ({@code localXOffset}, {@code localYOffset}) mm in the vertex's own
   * frame (x along its facing) and turns it by {@code thOffset} degrees.
   */
  public void setVertexOffset(int localXOffset, int localYOffset, double thOffset) {
    locked(
        () -> {
          this.localXOffset = localXOffset;
          this.localYOffset = localYOffset;
          this.thOffset = thOffset;
        });
  }

  /** The state. */
  public State getState() {
    return lockedGet(() -> state);
  }

  /** Whether the vertex has been seen since the last activation or search. */
  public boolean getVertexSeen() {
    return lockedGet(() -> vertexSeen);
  }

  /** The vertex in global coordinates (meaningful once seen). */
  public ArPose getVertex() {
    return lockedGet(
        () -> {
          ArRobot r = getRobot();
          return r == null ? vertex : r.getEncoderTransform().doTransform(vertex);
        });
  }

  /** The lines found in the last scan examined. */
  public List<ArLineFinderSegment> getLines() {
    return lockedGet(() -> lines);
  }

  /** Starts driving to the target (or fails at once without a laser). */
  @Override
  public void activate() {
    super.activate();
    locked(
        () -> {
          vertexSeen = false;
          ArRobot r = getRobot();
          vertexSeenLastNanos = r == null ? 0 : r.getClock().nanoTime();
          originalAngle = r == null ? Double.NaN : r.getTh();
          linesCounter = -1;
          if (laser == null && r != null) {
            laser = robotsLaser(r);
          }
          state = laser != null ? State.STATE_ACQUIRE : State.STATE_FAILED;
          if (laser == null) {
            log.warn(
                "{}: no laser: add one to the robot (addRangeDevice) or call setLaserScanSource",
                getName());
          }
        });
  }

  private static LaserScanSource robotsLaser(ArRobot r) {
    for (Object d : r.getRangeDeviceList()) {
      if (d instanceof LaserScanSource l) {
        return l;
      }
    }
    return null;
  }

  @Override
  public void deactivate() {
    super.deactivate();
    locked(() -> state = State.STATE_INACTIVE);
  }

  private ArPose poseFromVertex(ArRobot robot, double distFromVertex) {
    ArPose v = robot.getEncoderTransform().doTransform(vertex);
    double r = Math.toRadians(v.th());
    return new ArPose(v.x() + Math.cos(r) * distFromVertex, v.y() + Math.sin(r) * distFromVertex);
  }

  private long unseenMs(ArRobot robot) {
    return TimeUnit.NANOSECONDS.toMillis(robot.getClock().nanoTime() - vertexSeenLastNanos);
  }

  private boolean lostVertex(ArRobot robot) {
    return !vertexSeen && unseenMs(robot) > vertexUnseenStopMSecs;
  }

  private void findTriangle(ArRobot robot, boolean initial, boolean goStraight) {
    if (linesCounter != robot.getCounter() || linesScan == null) {
      LaserScan scan = laser == null ? null : laser.getLaserScan();
      linesScan = scan;
      lineFinder.setMaxDistBetweenPoints(maxDistBetweenLinePoints);
      lines = scan == null ? List.of() : lineFinder.getLines(scan);
      linesCounter = robot.getCounter();
    }
    ArPose pose = robot.getPose();
    ArPose last = robot.getEncoderTransform().doTransform(vertex);
    TriangleFinder.Vertex v = finder.find(lines, pose, initial, goStraight, last, originalAngle);
    if (v == null) {
      return;
    }
    ArPose used = v.pose();
    if (adjustVertex && linesScan != null) {
      used = adjusted(robot, v);
    }
    if (localXOffset != 0 || localYOffset != 0 || Math.abs(thOffset) > .00001) {
      ArPose shifted = ArTransform.ofPose(used).doTransform(new ArPose(localXOffset, localYOffset));
      used = new ArPose(shifted.x(), shifted.y(), ArMath.addAngle(v.pose().th(), thOffset));
    }
    vertex = robot.getEncoderTransform().inverse().doTransform(used);
    vertexSeen = true;
    vertexSeenLastNanos = robot.getClock().nanoTime();
  }

  /** The closest scan point in the box between the robot side of the vertex and the sides' ends. */
  private ArPose adjusted(ArRobot robot, TriangleFinder.Vertex v) {
    ArTransform toLocal = robot.getToLocalTransform();
    ArLineFinderSegment l1 = lines.get(v.lineIndex());
    ArLineFinderSegment l2 = lines.get(v.lineIndex() + 1);
    ArPose end1 = toLocal.doTransform(l1.getEndPoint1());
    ArPose end2 = toLocal.doTransform(l2.getEndPoint2());
    ArPose vl = toLocal.doTransform(v.pose());
    double minX = vl.x() - 100;
    double maxX = Math.max(end1.x(), end2.x());
    double minY = Math.min(end1.y(), end2.y());
    double maxY = Math.max(end1.y(), end2.y());
    ArPose best = null;
    double bestDist = Double.MAX_VALUE;
    for (int i = 0; i < linesScan.getNumPoints(); i++) {
      double lx = toLocal.transformX(linesScan.getX(i), linesScan.getY(i));
      double ly = toLocal.transformY(linesScan.getX(i), linesScan.getY(i));
      if (lx < minX || lx > maxX || ly < minY || ly > maxY) {
        continue;
      }
      double d = Math.hypot(lx, ly);
      if (d < bestDist) {
        bestDist = d;
        best = new ArPose(linesScan.getX(i), linesScan.getY(i));
      }
    }
    return best == null ? v.pose() : best.withTh(v.pose().th());
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    if (Double.isNaN(originalAngle)) {
      originalAngle = robot.getTh();
    }
    // Each state either answers or moves to another state; the bound guards against a cycle.
    for (int step = 0; step < 16; step++) {
      desired.reset();
      ArPose pose = robot.getPose();
      switch (state) {
        case STATE_INACTIVE -> {
          return null;
        }
        case STATE_SUCCEEDED, STATE_FAILED -> {
          desired.setVel(0);
          desired.setRotVel(0);
          return desired;
        }
        case STATE_ACQUIRE -> {
          findTriangle(robot, true, false);
          if (lostVertex(robot)) {
            state = acquire ? State.STATE_SEARCHING : failed();
            continue;
          }
          if (vertexSeen) {
            ArPose approach = poseFromVertex(robot, approachDistFromVertex);
            ArPose fin = poseFromVertex(robot, finalDistFromVertex);
            double toApproach = Math.abs(deltaHeadingTo(robot, approach));
            if (approachDistFromVertex <= 0
                || toApproach > 90
                || (toApproach > 45 && pose.findDistanceTo(fin) < pose.findDistanceTo(approach))) {
              state = gotoVertex ? State.STATE_GOTO_VERTEX : State.STATE_GOTO_FINAL;
            } else {
              state = State.STATE_GOTO_APPROACH;
            }
            continue;
          }
          desired.setVel(0);
          desired.setRotVel(0);
          return desired;
        }
        case STATE_SEARCHING -> {
          vertexSeen = false;
          findTriangle(robot, true, false);
          if (vertexSeen) {
            state = State.STATE_ACQUIRE;
            continue;
          }
          desired.setVel(0);
          desired.setRotVel(acquireTurnSpeed);
          return desired;
        }
        case STATE_GOTO_APPROACH -> {
          findTriangle(robot, false, false);
          if (lostVertex(robot)) {
            state = acquire ? State.STATE_SEARCHING : failed();
            continue;
          }
          ArPose approach = poseFromVertex(robot, approachDistFromVertex);
          double dist = pose.findDistanceTo(approach);
          double turn = Math.abs(deltaHeadingTo(robot, approach));
          if (dist < closeDist || (dist < closeDist * 2 && turn > 30)) {
            state = State.STATE_ALIGN_APPROACH;
            continue;
          }
          desired.setHeading(pose.findAngleTo(approach));
          double vel = Math.sqrt(dist * 400 * 2) * (180 - turn) / 180;
          desired.setVel(ArMath.clamp(vel, 0, speed));
          return desired;
        }
        case STATE_ALIGN_APPROACH, STATE_ALIGN_FINAL -> {
          double angle = pose.findAngleTo(poseFromVertex(robot, 0));
          if (Math.abs(ArMath.subAngle(robot.getTh(), angle)) < 2 && Math.abs(robot.getVel()) < 5) {
            if (state == State.STATE_ALIGN_FINAL) {
              log.info("{}: succeeded", getName());
              state = State.STATE_SUCCEEDED;
            } else {
              state = gotoVertex ? State.STATE_GOTO_VERTEX : State.STATE_GOTO_FINAL;
            }
            continue;
          }
          desired.setHeading(angle);
          desired.setVel(0);
          return desired;
        }
        case STATE_GOTO_VERTEX -> {
          ArPose fin = poseFromVertex(robot, 0);
          if (useIgnoreInGoto
              && pose.findDistanceTo(fin) > finalDistFromVertex + ignoreTriangleDist) {
            findTriangle(robot, false, true);
          }
          if (lostVertex(robot)) {
            state = failed();
            continue;
          }
          fin = poseFromVertex(robot, 0);
          double dist = pose.findDistanceTo(fin) - finalDistFromVertex;
          double angle = deltaHeadingTo(robot, fin);
          if (Math.abs(angle) > 10) {
            log.info(
                "{}: failing, would have to turn {} degrees to a target {} mm away",
                getName(),
                Math.round(angle),
                Math.round(dist));
            state = failed();
            continue;
          }
          desired.setDeltaHeading(angle);
          double vel = dist > 0 ? Math.sqrt(dist * 100 * 2) : 0;
          desired.setVel(ArMath.clamp(vel, 0, speed));
          if (dist <= 0 && Math.abs(robot.getVel()) < 5) {
            log.info("{}: succeeded (vertex)", getName());
            state = State.STATE_SUCCEEDED;
            continue;
          }
          return desired;
        }
        case STATE_GOTO_FINAL -> {
          ArPose fin = poseFromVertex(robot, finalDistFromVertex);
          if (pose.findDistanceTo(fin) > ignoreTriangleDist) {
            findTriangle(robot, false, false);
          }
          if (lostVertex(robot)) {
            state = acquire ? State.STATE_SEARCHING : failed();
            continue;
          }
          fin = poseFromVertex(robot, finalDistFromVertex);
          double dist = pose.findDistanceTo(fin);
          double angle = pose.findAngleTo(fin);
          double turn = Math.abs(deltaHeadingTo(robot, fin));
          double vel = robot.getVel();
          if (dist < 5
              || (vel > 0 && dist < closeDist && turn > 20)
              || (vel < 0 && dist < closeDist && turn < 160)
              || (Math.abs(vel) < 5 && dist < closeDist)) {
            state = State.STATE_ALIGN_FINAL;
            continue;
          }
          if (Math.abs(ArMath.subAngle(robot.getTh(), angle)) < 90) {
            desired.setHeading(angle);
            double v = Math.sqrt(dist * 100 * 2) * (45 - turn) / 45;
            desired.setVel(ArMath.clamp(v, 0, speed));
          } else {
            // Behind us: back up to it.
            desired.setHeading(ArMath.subAngle(angle, 180));
            double v =
                -Math.sqrt(dist * 100 * 2) * (45 - Math.abs(ArMath.subAngle(180, turn))) / 45;
            desired.setVel(ArMath.clamp(v, -speed, 0));
          }
          return desired;
        }
      }
    }
    log.warn("{}: state machine did not settle; stopping", getName());
    desired.reset();
    desired.setVel(0);
    desired.setRotVel(0);
    return desired;
  }

  private State failed() {
    log.info("{}: failed", getName());
    return State.STATE_FAILED;
  }

  private static double deltaHeadingTo(ArRobot robot, ArPose p) {
    return ArMath.subAngle(robot.getPose().findAngleTo(p), robot.getTh());
  }
}
