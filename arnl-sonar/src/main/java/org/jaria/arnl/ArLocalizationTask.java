package org.jaria.arnl;

import java.util.Objects;
import org.jaria.geom.ArPose;
import org.jaria.laser.ArLaser;
import org.jaria.map.ArMap;
import org.jaria.params.ArRobotParams;
import org.jaria.range.ArRangeDevice;
import org.jaria.range.LaserScanSource;
import org.jaria.robot.ArRobot;

/**
 * Laser Monte Carlo localization (ARNL's {@code ArLocalizationTask}): keeps the robot's pose on a
 * map using odometry and a laser range finder. Each beam's end point is looked up in a likelihood
 * field of the map (the distance to the nearest wall face, precomputed once), so an update of 2000
 * particles costs under a millisecond with every second beam of a 181-beam scan ({@code jaria bench
 * arnl}). Everything but the sensor is shared with sonar localization and described in {@link
 * ArBaseLocalizationTask}.
 *
 * <pre>{@code
 * ArSimulatedLaser laser = new ArSimulatedLaser();   // or an ArLMS2xx / ArUrg from ArLaserConnector
 * robot.addRangeDevice(laser);
 * ArLocalizationTask loc = new ArLocalizationTask(robot, laser, map); // own thread
 * loc.localizeRobotAtHomeBlocking();
 * ...
 * boolean ok = loc.getRobotIsLocalized();
 * }</pre>
 *
 * <p>Updates come every {@code TriggerDistance} mm or {@code TriggerAngle} degrees (100 mm and 3°
 * by default), with the newest complete scan, placed at the odometry pose the robot had when the
 * laser took it. Every {@code LaserBeamStep}-th beam is used (2 by default: 91 of a 181-beam scan).
 */
public final class ArLocalizationTask extends ArBaseLocalizationTask {

  /**
   * ARNL's constructor: localization on its own thread, default parameters in a config of its own,
   * seed 1.
   *
   * @param laser the laser on this robot: an {@link ArLaser} (its {@code setSensorPosition} says
   *     where it sits) or the simulator's laser (placed by the robot's parameters {@code LaserX},
   *     {@code LaserY}, {@code LaserTh})
   */
  public ArLocalizationTask(ArRobot robot, ArRangeDevice laser, ArMap map) {
    this(builder(robot, map).laser(laser));
  }

  private ArLocalizationTask(Builder b) {
    super(
        b,
        LocalizationParams.forLaser(b.configOrNew()),
        p -> new LaserFeed(b.robot, b.source, b.mount, b.maxRange, p));
  }

  /** A builder for the task with more options than ARNL's constructor. */
  public static Builder builder(ArRobot robot, ArMap map) {
    return new Builder(robot, map);
  }

  /** Options for {@link ArLocalizationTask}. */
  public static final class Builder extends BaseBuilder<Builder> {
    private LaserScanSource source;
    private ArPose mount;
    private double maxRange;

    private Builder(ArRobot robot, ArMap map) {
      super(robot, map, "laserLocalization");
    }

    @Override
    Builder self() {
      return this;
    }

    /**
     * The laser whose scans localize the robot: a range device that gives whole scans ({@link
     * LaserScanSource}), such as {@link ArLaser} or {@code ArSimulatedLaser}, on this robot.
     *
     * @throws NullPointerException if {@code laser} is null
     * @throws IllegalArgumentException if it gives no scans or belongs to another robot
     */
    public Builder laser(ArRangeDevice laser) {
      Objects.requireNonNull(laser, "laser: laser localization needs the robot's laser, not null");
      if (!(laser instanceof LaserScanSource s)) {
        throw new IllegalArgumentException(
            "'"
                + laser.getName()
                + "' gives no laser scans: pass an ArLaser (ArLMS2xx, ArUrg) or an"
                + " ArSimulatedLaser");
      }
      requireThisRobots(laser, "laser");
      ArPose at;
      if (laser instanceof ArLaser real) {
        at = real.getSensorPosition();
      } else {
        ArRobotParams rp = robot.getRobotParams();
        at = new ArPose(rp.getLaserX(), rp.getLaserY(), rp.getLaserTh());
      }
      return laser(s, at, laser.getMaxRange());
    }

    /**
     * Any source of scans (a test's synthetic laser, a recorded log), mounted at {@code mount} on
     * the robot, with readings at or beyond {@code maxRange} mm meaning "no echo".
     */
    public Builder laser(LaserScanSource scans, ArPose mount, double maxRange) {
      this.source = Objects.requireNonNull(scans, "scans");
      this.mount = Objects.requireNonNull(mount, "mount");
      if (!(maxRange > 0)) {
        throw new IllegalArgumentException("the laser's maximum range must be positive");
      }
      this.maxRange = maxRange;
      return this;
    }

    /** Creates the task, registers it on the robot and, if threaded, starts its thread. */
    public ArLocalizationTask build() {
      if (source == null) {
        throw new IllegalStateException(
            "no laser: call laser(...) on the builder with the robot's laser");
      }
      return new ArLocalizationTask(this);
    }
  }
}
