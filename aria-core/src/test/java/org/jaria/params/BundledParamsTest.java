package org.jaria.params;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** Sanity of every parameter file we ship, and spot checks of robots without a reference file. */
class BundledParamsTest {

  static Iterable<String> subtypes() {
    return ArRobotParams.BUNDLED_SUBTYPES;
  }

  @ParameterizedTest
  @MethodSource("subtypes")
  void everyBundledFileIsConsistent(String subtype) {
    ParamFile f = ArRobotParams.bundledFile(subtype).orElseThrow();
    ArRobotParams p = ArRobotParams.forSubtype(subtype);
    assertEquals(subtype, p.getSubClassName());
    assertEquals("Pioneer", p.getClassName());
    assertEquals(p.getNumSonar(), f.getAll("SonarUnit").size(), "one SonarUnit per sonar");
    assertEquals(p.getNumIR(), f.getAll("IRUnit").size(), "one IRUnit per IR");
    assertTrue(p.getRobotRadius() > 100 && p.getRobotRadius() <= 600);
    assertEquals(p.getRobotLength(), p.getRobotLengthFront() + p.getRobotLengthRear(), 1e-9);
    assertTrue(p.getAbsoluteMaxVelocity() > 0 && p.getAbsoluteMaxRotVelocity() > 0);
    for (int i = 0; i < p.getNumSonar(); i++) {
      // Every sonar sits on the body: within 10 mm of its outline circle.
      double r = Math.hypot(p.getSonarX(i), p.getSonarY(i));
      double body =
          Math.max(p.getRobotRadius(), Math.max(p.getRobotLength(), p.getRobotWidth()) / 2);
      assertTrue(r > 50 && r <= body + 10, subtype + " sonar " + i + " at " + r);
    }
    assertEquals(Optional.of(subtype), f.get("Subclass"));
  }

  @Test
  void robotsWithoutAReferenceFileHaveAriasValues() {
    ArRobotParams p2dx = ArRobotParams.forSubtype("p2dx");
    assertEquals(0.84, p2dx.getDistConvFactor());
    assertEquals(0.268, p2dx.getRangeConvFactor());
    assertEquals(17, p2dx.getLaserX());
    assertEquals(8, p2dx.getLaserY());

    ArRobotParams p2at = ArRobotParams.forSubtype("p2at");
    assertEquals(1.32, p2at.getDistConvFactor());
    assertEquals(500, p2at.getRobotRadius());
    assertEquals(1200, p2at.getAbsoluteMaxVelocity());

    ArRobotParams pb = ArRobotParams.forSubtype("peoplebot-sh");
    assertEquals(32, pb.getNumSonar());
    assertEquals(4, pb.getNumIR());
    assertEquals(333, pb.getIRX(1));
    assertEquals(233, pb.getIRY(1));
    assertEquals(256.5, pb.getRobotLengthFront());
    assertTrue(pb.haveTableSensingIR() && pb.haveNewTableSensingIR());
    assertTrue(pb.haveFrontBumpers() && pb.haveRearBumpers());
    assertTrue(pb.getRequestIOPackets());
    assertEquals(0.006, pb.getDiffConvFactor());

    ArRobotParams amigo = ArRobotParams.forSubtype("amigo");
    ArRobotParams amigoSh = ArRobotParams.forSubtype("amigo-sh");
    assertEquals(0.5083, amigo.getDistConvFactor());
    assertEquals(0.6154, amigo.getVelConvFactor());
    assertEquals(1.0, amigoSh.getDistConvFactor());
    assertEquals(8, amigoSh.getNumSonar());
    assertEquals(0.011, amigoSh.getDiffConvFactor());
    assertEquals(1000, amigoSh.getAbsoluteMaxVelocity());
    assertEquals(120, amigoSh.getSonarX(4));
    assertEquals(125, amigo.getSonarX(4));

    ArRobotParams lms = ArRobotParams.forSubtype("p3dx-sh-lms");
    assertEquals(55, lms.getLaserX());
    assertEquals(Optional.of("tcp"), lms.getRaw("LaserPortType"));
    assertEquals(16, lms.getNumSonar());
  }
}
