package org.jaria.range;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.IoPacket;
import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.Test;

/**
 * IR proximity sensors of a PeopleBot (four IRUnits in its parameter file: two table sensors at the
 * front, two cliff sensors at the sides), fed by the SIP's DIGIN byte or by IOpacs.
 */
class ArIRsTest {

  private static final int NOTHING = 0xFF; // IR bits are active-low

  private final LockstepRig rig = new LockstepRig();

  private ArIRs connect(String subtype, ArIRs irs) {
    rig.fake.identity("irbot", "Pioneer", subtype);
    rig.robot.addRangeDevice(irs);
    rig.sip.setIo(0, 0, 0, NOTHING, 0).setOptionalCount(5);
    assertTrue(rig.connect());
    rig.run(200);
    return irs;
  }

  /** Makes the SIP's DIGIN byte show the IRs in {@code triggered} (bit i = IR i). */
  private void sipDigIn(int triggered) {
    rig.sip.setIo(0, 0, 0, NOTHING & ~triggered, 0);
  }

  private static void assertPoint(double x, double y, ArPose p) {
    assertEquals(x, p.x(), 1e-6, "x of " + p);
    assertEquals(y, p.y(), 1e-6, "y of " + p);
  }

  @Test
  void aTriggeredIrPutsAReadingWhereTheSensorSits() {
    ArIRs irs = connect("peoplebot-sh", new ArIRs());
    assertEquals(0, irs.getCurrentReadings().size(), "nothing seen while every bit is high");
    sipDigIn(1 << 1); // IRUnit 1 at (333, 233)
    rig.run(100);
    List<ArPose> seen = irs.getCurrentReadings();
    assertEquals(1, seen.size(), seen.toString());
    assertPoint(333, 233, seen.get(0));
    assertEquals(1, irs.getCumulativeReadings().size());
    assertEquals(Math.hypot(333, 233), irs.currentReadingPolar(0, 90), 1e-6);
    assertEquals(5000, irs.currentReadingPolar(-90, 0), "nothing on the right");
  }

  @Test
  void readingsAreInGlobalCoordinates() {
    ArIRs irs = connect("peoplebot-sh", new ArIRs());
    rig.robot.moveTo(new ArPose(1000, 500, 90));
    sipDigIn(1 << 1); // (333, 233) in the robot's frame: 333 ahead (+y), 233 to the left (-x)
    rig.run(100);
    assertPoint(1000 - 233, 500 + 333, irs.getCurrentReadings().get(0));
  }

  @Test
  void iopacTableSensorsTakeOverFromTheSipWhenTheyArrive() throws IOException {
    ArIRs irs = connect("peoplebot-sh", new ArIRs());
    sipDigIn(1 << 1); // the SIP says IR 1 ...
    int[] digIn = {0, 0, 0, NOTHING & ~(1 << 2)}; // ... the IOpac's fourth byte says IR 2
    rig.fake.send(new IoPacket(digIn, new int[] {0}, new int[0]).encode(new ArRobotPacket()));
    rig.run(100);
    List<ArPose> seen = irs.getCurrentReadings();
    assertEquals(1, seen.size(), seen.toString());
    assertPoint(-2, -116, seen.get(0)); // IRUnit 2: NewTableSensingIR reads the IOpac
  }

  @Test
  void readingsAreForgottenAfterTheKeepTime() {
    ArIRs irs = connect("peoplebot-sh", new ArIRs("irs", 1));
    sipDigIn(1); // IRUnit 0 for one SIP
    rig.run(100);
    sipDigIn(0);
    assertEquals(1, irs.getCurrentReadings().size());
    rig.run(800);
    assertEquals(1, irs.getCurrentReadings().size(), "still within the 1 s keep time");
    assertEquals(1, irs.getCumulativeReadings().size());
    rig.run(400);
    assertEquals(0, irs.getCurrentReadings().size(), "older than 1 s");
    assertEquals(0, irs.getCumulativeReadings().size());
  }

  @Test
  void aRobotWithoutIrUnitsNeverReports() {
    ArIRs irs = connect("p3dx-sh", new ArIRs());
    sipDigIn(0xFF); // every bit low
    rig.run(300);
    assertEquals(0, irs.getCurrentReadings().size());
    assertTrue(rig.robot.findSensorInterpTask("irs") != null, "the task runs all the same");
  }
}
