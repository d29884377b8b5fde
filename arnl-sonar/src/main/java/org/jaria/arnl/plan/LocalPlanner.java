package org.jaria.arnl.plan;

/**
 * The dynamic window local planner: every cycle it tries pairs of translational and rotational
 * velocity the robot can reach within a short time, drives each ahead for a couple of seconds on
 * paper, throws away those that hit an obstacle (mapped or sensed) too soon to brake, and picks the
 * pair that best combines heading towards a point ahead on the global path, closeness to the path,
 * clearance and speed. Allocates nothing per cycle. Not thread-safe.
 */
public final class LocalPlanner {

  /**
   * Settings.
   *
   * @param maxVel top speed, mm/s
   * @param maxRotVel top rotational speed, deg/s
   * @param accel translational acceleration assumed, mm/s²
   * @param decel translational deceleration for braking checks, mm/s²
   * @param rotAccel rotational acceleration assumed, deg/s²
   * @param radius the robot counts as touching a mapped obstacle closer than this to its centre, mm
   * @param front distance from the robot's centre to its front, mm (for sensed obstacles, which are
   *     checked against the robot's rectangle)
   * @param rear distance from the centre to the rear, mm
   * @param half half the robot's width, mm
   * @param side clearance wanted between the robot's rectangle and a sensed obstacle, mm
   * @param horizon how far ahead trajectories are driven, s
   * @param window how far the velocity window reaches, s of acceleration
   * @param linSamples translational velocities tried
   * @param rotSamples rotational velocities tried
   * @param headingWt weight of heading towards the point ahead on the path
   * @param distanceWt weight of staying near the path
   * @param clearanceWt weight of clearance
   * @param velocityWt weight of speed
   * @param lookahead distance along the path to the point steered at, mm (at least)
   * @param alignAngle if the point ahead is further off than this, degrees, turn in place first
   */
  public record Params(
      double maxVel,
      double maxRotVel,
      double accel,
      double decel,
      double rotAccel,
      double radius,
      double front,
      double rear,
      double half,
      double side,
      double horizon,
      double window,
      int linSamples,
      int rotSamples,
      double headingWt,
      double distanceWt,
      double clearanceWt,
      double velocityWt,
      double lookahead,
      double alignAngle) {}

  /**
   * The chosen command.
   *
   * @param vel translational velocity, mm/s
   * @param rotVel rotational velocity, deg/s
   * @param blocked true if no trajectory moving forward was safe
   * @param margin the robot's current margin: the smaller of (clearance to mapped obstacles −
   *     radius) and (distance from the robot's rectangle to sensed obstacles − side clearance), mm;
   *     negative when too close
   */
  public record Command(double vel, double rotVel, boolean blocked, double margin) {}

  /** Distance from a point to the nearest mapped obstacle (walls, forbidden lines), mm. */
  @FunctionalInterface
  public interface ClearanceMap {
    /** Clearance at (x, y), mm. */
    double clearanceAt(double x, double y);
  }

  private static final double DT = 0.1;

  private double minX;
  private double minY;
  private double maxX;
  private double maxY;

  /**
   * Chooses a command.
   *
   * @param x robot x, mm
   * @param y robot y, mm
   * @param thDeg robot heading, degrees
   * @param vel current translational velocity, mm/s
   * @param rotVel current rotational velocity, deg/s
   * @param path the global path
   * @param index the path point nearest the robot
   * @param speedCap top speed for this cycle (e.g. lower near the goal), mm/s
   * @param map clearance to mapped obstacles
   * @param obsX x of sensed obstacle points
   * @param obsY y of sensed obstacle points
   * @param nObs number of sensed points
   * @param p settings
   */
  public Command plan(
      double x,
      double y,
      double thDeg,
      double vel,
      double rotVel,
      PlannedPath path,
      int index,
      double speedCap,
      ClearanceMap map,
      double[] obsX,
      double[] obsY,
      int nObs,
      Params p) {
    double th = Math.toRadians(thDeg);
    double here = margin(x, y, th, map, obsX, obsY, nObs, p);
    double look = Math.max(p.lookahead(), 1.5 * Math.abs(vel));
    int target = path.indexAhead(index, look);
    double tx = path.x(target);
    double ty = path.y(target);
    double toTarget = Math.atan2(ty - y, tx - x);
    double off = wrap(toTarget - th);
    minX = x;
    maxX = x;
    minY = y;
    maxY = y;
    double wMax = Math.toRadians(p.maxRotVel());
    if (Math.abs(Math.toDegrees(off)) > p.alignAngle() || Math.hypot(tx - x, ty - y) < 1) {
      double w = Math.max(-wMax, Math.min(wMax, 1.5 * off));
      if (Math.hypot(tx - x, ty - y) < 1) {
        w = 0;
      }
      if (w != 0 && !turnClear(x, y, th, off, here, map, obsX, obsY, nObs, p)) {
        // The robot's corners would sweep into something on the short way round: take the long
        // way if that is clear, else report blocked (the follower then backs off or replans).
        double longWay = off > 0 ? off - 2 * Math.PI : off + 2 * Math.PI;
        if (!turnClear(x, y, th, longWay, here, map, obsX, obsY, nObs, p)) {
          return new Command(0, 0, true, here);
        }
        w = Math.signum(longWay) * Math.max(Math.abs(w), Math.min(wMax, Math.toRadians(20)));
      }
      return new Command(0, Math.toDegrees(w), false, here);
    }
    double vTop = Math.max(0, Math.min(p.maxVel(), speedCap));
    double vLo = Math.max(0, Math.min(vTop, vel - p.decel() * p.window()));
    double vHi = Math.min(vTop, Math.max(0, vel) + p.accel() * p.window());
    double w0 = Math.toRadians(rotVel);
    double dw = Math.toRadians(p.rotAccel()) * p.window();
    double wLo = Math.max(-wMax, w0 - dw);
    double wHi = Math.min(wMax, w0 + dw);
    int steps = Math.max(1, (int) Math.round(p.horizon() / DT));
    double bestScore = Double.NEGATIVE_INFINITY;
    double bestV = 0;
    double bestW = 0;
    int window = Math.max(10, (int) (3 * look / 50));
    for (int a = 0; a < p.linSamples(); a++) {
      double v = p.linSamples() == 1 ? vHi : vLo + (vHi - vLo) * a / (p.linSamples() - 1);
      if (v <= 1) {
        continue;
      }
      for (int b = 0; b < p.rotSamples(); b++) {
        double w = p.rotSamples() == 1 ? 0 : wLo + (wHi - wLo) * b / (p.rotSamples() - 1);
        double cx = x;
        double cy = y;
        double ct = th;
        double minClear = here;
        double travelled = 0;
        double hitAt = Double.MAX_VALUE;
        for (int k = 0; k < steps; k++) {
          ct += w * DT * 0.5;
          cx += v * DT * Math.cos(ct);
          cy += v * DT * Math.sin(ct);
          ct += w * DT * 0.5;
          travelled += v * DT;
          double c = margin(cx, cy, ct, map, obsX, obsY, nObs, p);
          if (c < minClear) {
            minClear = c;
          }
          if (c < 0 && c < here) {
            hitAt = travelled;
            break;
          }
        }
        minX = Math.min(minX, cx);
        maxX = Math.max(maxX, cx);
        minY = Math.min(minY, cy);
        maxY = Math.max(maxY, cy);
        if (hitAt < Double.MAX_VALUE) {
          // Admissible only if the robot can still brake before it (after one more cycle).
          double room = hitAt - v * DT;
          if (room <= 0 || v > Math.sqrt(2 * p.decel() * room)) {
            continue;
          }
        }
        double heading = 1 - Math.abs(wrap(Math.atan2(ty - cy, tx - cx) - ct)) / Math.PI;
        double dPath = path.distanceToPath(cx, cy, index, window);
        double near = 1 - Math.min(dPath, 1000) / 1000;
        double clear = Math.max(0, Math.min(minClear, 1000)) / 1000;
        double speed = p.maxVel() > 0 ? v / p.maxVel() : 0;
        double score =
            p.headingWt() * heading
                + p.distanceWt() * near
                + p.clearanceWt() * clear
                + p.velocityWt() * speed;
        if (score > bestScore) {
          bestScore = score;
          bestV = v;
          bestW = w;
        }
      }
    }
    if (bestScore == Double.NEGATIVE_INFINITY) {
      // Nothing forward is safe: stop, and turn towards the path if it is off to a side.
      double w = Math.abs(off) > Math.toRadians(10) ? Math.max(-wMax, Math.min(wMax, off)) : 0;
      return new Command(0, Math.toDegrees(w), true, here);
    }
    return new Command(bestV, Math.toDegrees(bestW), false, here);
  }

  /**
   * Whether turning on the spot by {@code turn} radians (at most the first 60°, enough to be free
   * of what is near now) keeps the robot's rectangle clear: it may not get closer than the side
   * clearance to anything it is not already that close to.
   */
  private static boolean turnClear(
      double x,
      double y,
      double th,
      double turn,
      double here,
      ClearanceMap map,
      double[] ox,
      double[] oy,
      int n,
      Params p) {
    double span = Math.min(Math.abs(turn), Math.toRadians(60));
    double step = Math.toRadians(5);
    double floor = Math.min(0, here) - 5;
    for (double a = step; a <= span + 1e-9; a += step) {
      if (margin(x, y, th + Math.signum(turn) * a, map, ox, oy, n, p) < floor) {
        return false;
      }
    }
    return true;
  }

  /** How much room the robot has at (x, y, th): negative when it would touch something. */
  private static double margin(
      double x, double y, double th, ClearanceMap map, double[] ox, double[] oy, int n, Params p) {
    double m = map.clearanceAt(x, y) - p.radius();
    if (n == 0) {
      return m;
    }
    double c = Math.cos(th);
    double s = Math.sin(th);
    double reach = m + p.side() + Math.max(Math.max(p.front(), p.rear()), p.half());
    double reach2 = reach * reach;
    for (int i = 0; i < n; i++) {
      double dx = ox[i] - x;
      double dy = oy[i] - y;
      if (dx * dx + dy * dy > reach2) {
        continue;
      }
      double lx = c * dx + s * dy;
      double ly = -s * dx + c * dy;
      double ex = Math.max(Math.max(-p.rear() - lx, lx - p.front()), 0);
      double ey = Math.max(Math.abs(ly) - p.half(), 0);
      double d;
      if (ex > 0 || ey > 0) {
        d = Math.sqrt(ex * ex + ey * ey);
      } else {
        // Inside the rectangle: minus the way out.
        d = -Math.min(Math.min(p.front() - lx, lx + p.rear()), p.half() - Math.abs(ly));
      }
      double mm = d - p.side();
      if (mm < m) {
        m = mm;
      }
    }
    return m;
  }

  /** The area the last search looked at: min x, min y, max x, max y (mm). */
  public double[] searchArea() {
    return new double[] {minX, minY, maxX, maxY};
  }

  private static double wrap(double a) {
    return Math.atan2(Math.sin(a), Math.cos(a));
  }
}
