package org.jaria.sim.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.function.Function;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.ptz.ArDPPTU;
import org.jaria.ptz.ArPTZ;
import org.jaria.ptz.ArSonyPTZ;
import org.jaria.ptz.ArVCC4;
import org.jaria.robot.ArRobot;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * One sign for every pan-tilt unit: ARIA's, pan positive to the right. Each driver (Sony, Directed
 * Perception, Canon VC-C4) pans +30° through the robot's AUX port to the simulator's emulation of
 * its unit; the head reports 30° to the right, the simulated camera following it looks 30° right of
 * the robot's heading, and a red ball standing 30° to the robot's right is in the middle of the
 * picture.
 */
class PtzSignTest {

  /**
   * A 10 m square room, the robot at its centre facing +x, a red ball 2 m away 30° to the right.
   */
  private static SimWorld room() {
    List<ArLineSegment> walls =
        List.of(
            new ArLineSegment(-5000, -5000, 5000, -5000),
            new ArLineSegment(5000, -5000, 5000, 5000),
            new ArLineSegment(5000, 5000, -5000, 5000),
            new ArLineSegment(-5000, 5000, -5000, -5000));
    SimWorld w = SimWorld.ofLines(walls, new ArPose(0, 0, 0), SimOptions.builder().seed(5).build());
    // The camera sits 100 mm ahead of the robot's centre: the ball is 30° right of it from there.
    double a = Math.toRadians(-30);
    w.coloredObjects()
        .add(
            ColoredObject.cylinder(
                "ball", 100 + 2000 * Math.cos(a), 2000 * Math.sin(a), 200, 250, 0xD02020),
            false);
    return w;
  }

  private static Function<ArRobot, ArPTZ> driver(String type) {
    return switch (type) {
      case "sony" -> ArSonyPTZ::new;
      case "dpptu" -> ArDPPTU::new;
      case "vcc4" -> ArVCC4::new;
      default -> throw new IllegalArgumentException(type);
    };
  }

  /** Mean column of red pixels, or NaN. */
  private static double redColumn(SimCamera cam) {
    int w = cam.getWidth();
    int[] img = new int[w * cam.getHeight()];
    cam.render(img);
    long sum = 0;
    int n = 0;
    for (int i = 0; i < img.length; i++) {
      int r = (img[i] >> 16) & 0xFF;
      int g = (img[i] >> 8) & 0xFF;
      int b = img[i] & 0xFF;
      if (r > 100 && r > 2 * g && r > 2 * b) {
        sum += i % w;
        n++;
      }
    }
    return n == 0 ? Double.NaN : (double) sum / n;
  }

  @ParameterizedTest
  @ValueSource(strings = {"sony", "dpptu", "vcc4"})
  void panningRightTurnsTheHeadAndTheCameraRight(String type) {
    try (SimWorld world = room()) {
      SimRobot body = world.addRobot(RobotOptions.of("p3dx-sh").withPtzType(type));
      SimCamera cam = SimCamera.onTop(world, body);
      cam.setFollowAuxPtz(true);
      try (SimulatedRobot sim = SimulatedRobot.connect(world, body)) {
        ArPTZ ptz = driver(type).apply(sim.robot());
        assertEquals(type, ptz.getTypeName());
        assertTrue(ptz.init());
        sim.runMillis(2000);
        double ahead = redColumn(cam);
        assertTrue(
            Double.isNaN(ahead) || ahead > cam.getWidth() / 2.0 + 10,
            "looking ahead, the ball is off to the right: " + ahead);

        assertTrue(ptz.panTilt(30, -10));
        sim.runMillis(2000); // the VC-C4's frames are paced, 300 ms apart
        assertEquals(30, ptz.getPan(), 1e-9, "the driver remembers what it was asked");
        assertEquals(30, body.getPtzPointing().panRightDeg(), 0.1, "the head turned right");
        assertEquals(30, cam.getPan(), 0.1, "the camera follows with the same sign");
        assertEquals(body.getTruePose().th() - 30, cam.getViewPose().th(), 0.1, "it looks right");
        assertEquals(cam.getWidth() / 2.0, redColumn(cam), 3, "the ball is in the middle");
      }
    }
  }
}
