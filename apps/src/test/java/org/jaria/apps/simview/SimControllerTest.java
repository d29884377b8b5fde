package org.jaria.apps.simview;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimObstacle;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;

class SimControllerTest {

  @Test
  void stepPauseRunAndSpeed() {
    try (SimWorld w = SimWorld.bundled("hall", SimOptions.defaults())) {
      w.addRobot("p3dx-sh");
      SimController c = new SimController(w, 2);
      c.step(100);
      assertEquals(10, w.getStepCount());
      c.run();
      assertTrue(w.isRealTime());
      assertThrows(IllegalStateException.class, () -> c.step(100));
      c.setSpeedup(5);
      assertEquals(5, c.speedup());
      assertTrue(w.isRealTime());
      c.pause();
      assertFalse(w.isRealTime());
      assertFalse(c.isRunning());
    }
  }

  @Test
  void placeMoveAndAdd() {
    try (SimWorld w = SimWorld.bundled("hall", SimOptions.defaults())) {
      w.addRobot("p3dx-sh");
      SimController c = new SimController(w, 1);
      c.placeRobot(0, new ArPose(3000, 4000, 45));
      assertEquals(new ArPose(3000, 4000, 45), w.getRobot(0).getTruePose());
      SimObstacle box = c.addBox(1000, 1000, 0, 0);
      assertEquals(4, box.segments().size());
      SimObstacle moved = c.moveObstacle(box, 100, 200);
      assertEquals(List.of(moved), w.getObstacles());
      assertEquals(box.segments().get(0).x1() + 100, moved.segments().get(0).x1(), 1e-9);
      assertTrue(c.removeObstacle(moved));
      assertTrue(w.getObstacles().isEmpty());
    }
  }

  @Test
  void odometryFootprintFollowsTheOdometryPose() {
    List<ArPose> fp = List.of(new ArPose(110, 100), new ArPose(90, 100));
    List<ArPose> s = SimRenderer.shifted(fp, new ArPose(100, 100, 0), new ArPose(0, 0, 90));
    assertEquals(0, s.get(0).x(), 1e-9);
    assertEquals(10, s.get(0).y(), 1e-9);
    assertEquals(-10, s.get(1).y(), 1e-9);
    assertTrue(
        SimCanvas.inside(
            List.of(new ArPose(0, 0), new ArPose(10, 0), new ArPose(10, 10), new ArPose(0, 10)),
            5,
            5));
  }
}
