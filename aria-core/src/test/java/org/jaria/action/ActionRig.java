package org.jaria.action;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.testing.LockstepRig;

/**
 * A connected robot with a sonar device on the lockstep rig, and helpers to put it in a situation:
 * sonar readings, speed, pose, stall and bumper bits, extra packets.
 */
final class ActionRig {

  final LockstepRig rig = new LockstepRig();
  final ArSonarDevice sonar = new ArSonarDevice();

  /** A P3-DX (p3dx-sh), connected, with a few cycles run. */
  ActionRig() {
    this("p3dx-sh");
  }

  /** A robot of the given subtype, connected. */
  ActionRig(String subtype) {
    rig.fake.identity("fake", "Pioneer", subtype);
    rig.robot.addRangeDevice(sonar);
    assertTrue(rig.connect(), "the rig robot connects");
    rig.run(200);
  }

  ArRobot robot() {
    return rig.robot;
  }

  /** Sends one reading of sonar {@code n} and runs a cycle. */
  ActionRig sonar(int n, int range) {
    rig.sip.clearSonar().addSonar(n, range);
    rig.run(100);
    rig.sip.clearSonar();
    return this;
  }

  /** Every sonar reads "no echo". */
  ActionRig clearSonar() {
    rig.sip.clearSonar();
    for (int i = 0; i < 16; i++) {
      rig.sip.addSonar(i, 5000);
    }
    rig.run(100);
    rig.sip.clearSonar();
    return this;
  }

  /** Both wheels at {@code mmPerSec}; runs a cycle. */
  ActionRig vel(int mmPerSec) {
    rig.sip.setWheelVels(mmPerSec, mmPerSec);
    rig.run(100);
    return this;
  }

  /** Sets the stall and bumper word; runs a cycle. */
  ActionRig stallAndBumpers(int bits) {
    rig.sip.setStallAndBumpers(bits);
    rig.run(100);
    return this;
  }

  /** Declares the robot at {@code pose} (global). */
  ActionRig pose(double x, double y, double th) {
    rig.robot.moveTo(new ArPose(x, y, th));
    return this;
  }

  /** Sends a packet from the robot; runs a cycle so it is handled. */
  ActionRig send(ArRobotPacket p) {
    try {
      rig.fake.send(p);
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
    rig.run(100);
    return this;
  }

  /** Runs {@code ms} of virtual time. */
  ActionRig run(long ms) {
    rig.run(ms);
    return this;
  }

  /** Gives {@code a} this robot without adding it (so only the test fires it). */
  <A extends ArAction> A attach(A a) {
    a.setRobot(rig.robot);
    return a;
  }

  /** Fires {@code a} with nothing asked for by higher priorities. */
  static ArActionDesired fire(ArAction a) {
    return a.fire(new ArActionDesired());
  }

  /** Distance from the robot's centre of a reading of sonar 3 or 4 (the front pair). */
  static double frontSonarDistance(int range) {
    double a = Math.toRadians(10);
    return Math.hypot(166 + range * Math.cos(a), 27 + range * Math.sin(a));
  }
}
