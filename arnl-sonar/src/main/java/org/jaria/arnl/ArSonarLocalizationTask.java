package org.jaria.arnl;

import java.util.Objects;
import org.jaria.map.ArMap;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;

/**
 * Sonar Monte Carlo localization (SonARNL's {@code ArSonarLocalizationTask}): keeps the robot's
 * pose on a line map using odometry and the sonar ring. Everything but the sensor is shared with
 * laser localization and described in {@link ArBaseLocalizationTask}.
 *
 * <pre>{@code
 * ArSonarLocalizationTask loc = new ArSonarLocalizationTask(robot, sonar, map); // own thread
 * loc.localizeRobotAtHomeBlocking();
 * ...
 * double score = loc.getLocalizationScore();
 * }</pre>
 *
 * <p>Updates come every {@code TriggerDistance} mm or {@code TriggerAngle} degrees (200 mm and 5°
 * by default, as in the thesis), with the echo of every transducer that reported since the last.
 */
public final class ArSonarLocalizationTask extends ArBaseLocalizationTask {

  /**
   * ARNL's constructor: localization on its own thread, default parameters in a config of its own,
   * seed 1.
   */
  public ArSonarLocalizationTask(ArRobot robot, ArSonarDevice sonar, ArMap map) {
    this(builder(robot, map).sonar(sonar));
  }

  private ArSonarLocalizationTask(Builder b) {
    super(
        b,
        new LocalizationParams(b.configOrNew()),
        p -> new SonarFeed(Objects.requireNonNull(b.robot, "robot"), p));
  }

  /** A builder for the task with more options than ARNL's constructor. */
  public static Builder builder(ArRobot robot, ArMap map) {
    return new Builder(robot, map);
  }

  /** Options for {@link ArSonarLocalizationTask}. */
  public static final class Builder extends BaseBuilder<Builder> {

    private Builder(ArRobot robot, ArMap map) {
      super(robot, map, "sonarLocalization");
    }

    @Override
    Builder self() {
      return this;
    }

    /**
     * The sonar whose echoes localize the robot: the sonar ring of this robot. The filter reads the
     * ring's echoes from the robot's SIPs, where the device takes them too, so the device must not
     * belong to another robot.
     *
     * @throws NullPointerException if {@code sonar} is null: sonar localization needs the sonar
     * @throws IllegalArgumentException if {@code sonar} was added to another robot
     */
    public Builder sonar(ArSonarDevice sonar) {
      Objects.requireNonNull(
          sonar, "sonar: sonar localization needs the robot's ArSonarDevice, not null");
      requireThisRobots(sonar, "sonar");
      return this;
    }

    /** Creates the task, registers it on the robot and, if threaded, starts its thread. */
    public ArSonarLocalizationTask build() {
      return new ArSonarLocalizationTask(this);
    }
  }
}
