package org.jaria.sim;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.sim.robot.LaserModel;
import org.jaria.sim.robot.RobotBody;
import org.jaria.sim.robot.RobotModel;
import org.jaria.sim.robot.SonarModel;
import org.jaria.sim.server.ArcosSession;

/** Copies robot state into the immutable API types (called under the world's lock). */
final class Views {

  private Views() {}

  static SimSnapshot.RobotView robot(RobotSlot s) {
    RobotBody b = s.body;
    List<SimSnapshot.SonarView> sonar = new ArrayList<>(b.sonar().size());
    for (int i = 0; i < b.sonar().size(); i++) {
      SonarTruth t = sonarTruth(b, i);
      sonar.add(
          new SimSnapshot.SonarView(
              t.sensorX(),
              t.sensorY(),
              t.sensorThDeg(),
              b.sonar().options().coneDegrees(),
              t.reportedRangeMm(),
              t.hasEcho()));
    }
    ArcosSession ses = s.session();
    return new SimSnapshot.RobotView(
        b.index(),
        b.name(),
        b.model().getSubtype(),
        b.getTruePose(),
        b.getOdometryPose(),
        b.footprint().corners(),
        sonar,
        laser(b),
        b.getStallBits(),
        b.motion().getVel(),
        b.motion().getRotVel(),
        b.motion().areMotorsEnabled(),
        ses != null,
        ses != null && ses.state() == ArcosSession.State.OPEN);
  }

  static SonarTruth sonarTruth(RobotBody b, int i) {
    RobotModel m = b.model();
    SonarModel s = b.sonar();
    double th = Math.toRadians(b.trueTh());
    double c = Math.cos(th);
    double sn = Math.sin(th);
    double x = b.trueX() + c * m.getSonarX(i) - sn * m.getSonarY(i);
    double y = b.trueY() + sn * m.getSonarX(i) + c * m.getSonarY(i);
    return new SonarTruth(
        i,
        s.fireCount(i),
        s.trueRange(i),
        s.reportedRange(i),
        s.hitX(i),
        s.hitY(i),
        x,
        y,
        org.jaria.geom.ArMath.fixAngle(b.trueTh() + m.getSonarTh(i)));
  }

  static SimLaserScan laser(RobotBody b) {
    LaserModel l = b.laser();
    if (l == null || l.lastCount() == 0) {
      return null;
    }
    int[] ranges = l.ranges();
    int max = (int) Math.round(b.model().getLaserMaxRange());
    for (int k = 0; k < ranges.length; k++) {
      if (!l.echo(k)) {
        ranges[k] = max; // drawn to the end of the beam, as the record says
      }
    }
    return new SimLaserScan(
        new ArPose(l.originX(), l.originY(), l.originTh()), l.getStart(), l.beamSpacing(), ranges);
  }
}
