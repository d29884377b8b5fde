package org.jaria.arnl;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.jaria.arnl.mcl.SonarScan;
import org.jaria.geom.ArPose;
import org.jaria.range.ArSensorReading;
import org.jaria.robot.ArRobot;

/**
 * The sonar ring as a {@link ScanFeed}: the newest echo of each transducer (read from the robot's
 * SIPs), each with the odometry pose it was taken at, so that echoes of a moving robot are placed
 * where they were heard.
 */
final class SonarFeed implements ScanFeed {

  private final ArRobot robot;
  private final LocalizationParams params;

  // Cycle thread only.
  private final long[] lastCounter = new long[64];
  private final ArSensorReading[] latest = new ArSensorReading[64];
  private long lastTakenCounter = -1;

  SonarFeed(ArRobot robot, LocalizationParams params) {
    this.robot = robot;
    this.params = params;
    Arrays.fill(lastCounter, Long.MIN_VALUE);
  }

  @Override
  public void note() {
    int ns = Math.min(robot.getNumSonar(), latest.length);
    for (int i = 0; i < ns; i++) {
      ArSensorReading r = robot.getSonarReading(i);
      if (r != null && r.range() >= 0 && r.counterTaken() != lastCounter[i]) {
        lastCounter[i] = r.counterTaken();
        latest[i] = r;
      }
    }
  }

  @Override
  public SonarScan takeFresh(ArPose encoderNow) {
    int ns = Math.min(robot.getNumSonar(), latest.length);
    List<ArSensorReading> fresh = new ArrayList<>(ns);
    long newest = lastTakenCounter;
    for (int i = 0; i < ns; i++) {
      ArSensorReading r = latest[i];
      if (r != null && r.counterTaken() > lastTakenCounter) {
        fresh.add(r);
        newest = Math.max(newest, r.counterTaken());
      }
    }
    lastTakenCounter = newest;
    return prepare(fresh, encoderNow);
  }

  /** Latest reading of every transducer, taken within the last 3 s. */
  @Override
  public SonarScan current(ArPose encoderNow) {
    long now = robot.getClock().nanoTime();
    List<ArSensorReading> out = new ArrayList<>();
    for (int i = 0; i < robot.getNumSonar(); i++) {
      ArSensorReading r = robot.getSonarReading(i);
      if (r != null && r.range() >= 0 && now - r.timeTaken() <= TimeUnit.SECONDS.toNanos(3)) {
        out.add(r);
      }
    }
    return prepare(out, encoderNow);
  }

  private SonarScan prepare(List<ArSensorReading> readings, ArPose encoderNow) {
    return SonarScan.prepare(
        readings,
        encoderNow,
        params.sonarMinRange.getDouble(),
        params.sonarMaxRange.getDouble(),
        params.coneHalfAngle.getDouble(),
        params.arcSamples.getInt());
  }

  @Override
  public String what() {
    return "sonar echoes";
  }
}
