package org.jaria.sim.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;

class SimCameraTest {

  /** A square room 10 m wide with the robot at its centre facing +x. */
  private static SimWorld room() {
    List<ArLineSegment> walls =
        List.of(
            new ArLineSegment(-5000, -5000, 5000, -5000),
            new ArLineSegment(5000, -5000, 5000, 5000),
            new ArLineSegment(5000, 5000, -5000, 5000),
            new ArLineSegment(-5000, 5000, -5000, -5000));
    return SimWorld.ofLines(walls, new ArPose(0, 0, 0), SimOptions.builder().seed(5).build());
  }

  private static boolean reddish(int rgb) {
    int r = (rgb >> 16) & 0xFF;
    int g = (rgb >> 8) & 0xFF;
    int b = rgb & 0xFF;
    return r > 100 && r > 2 * g && r > 2 * b;
  }

  /** Column range [min, max] of red pixels, or null. */
  private static int[] redColumns(int[] img, int w, int h) {
    int min = Integer.MAX_VALUE;
    int max = -1;
    for (int i = 0; i < w * h; i++) {
      if (reddish(img[i])) {
        min = Math.min(min, i % w);
        max = Math.max(max, i % w);
      }
    }
    return max < 0 ? null : new int[] {min, max};
  }

  @Test
  void aBallAheadIsRedInTheMiddleAndMovesWithPan() {
    try (SimWorld world = room()) {
      SimRobot robot = world.addRobot("p3dx-sh");
      world
          .coloredObjects()
          .add(ColoredObject.cylinder("ball", 2000, 0, 250, 250, 0xD02020), false);
      SimCamera cam = SimCamera.onTop(world, robot);
      cam.setPanTilt(0, -10);
      int[] img = new int[cam.getWidth() * cam.getHeight()];
      cam.render(img);
      int[] cols = redColumns(img, cam.getWidth(), cam.getHeight());
      assertTrue(cols != null, "the ball is seen");
      double centre = (cols[0] + cols[1]) / 2.0;
      assertEquals(cam.getWidth() / 2.0, centre, 3, "straight ahead");
      cam.setPanTilt(
          -10, -10); // camera looks left (ARIA's sign): the ball moves right in the image
      cam.render(img);
      int[] panned = redColumns(img, cam.getWidth(), cam.getHeight());
      assertTrue((panned[0] + panned[1]) / 2.0 > centre + 10);
      cam.setZoom(SimCamera.MAX_ZOOM / 2);
      cam.setPanTilt(0, -10);
      cam.render(img);
      int[] zoomed = redColumns(img, cam.getWidth(), cam.getHeight());
      assertTrue(zoomed[1] - zoomed[0] > 2 * (cols[1] - cols[0]), "zoom makes it bigger");
    }
  }

  /** Mean row of red pixels, or NaN. */
  private static double redRow(int[] img, int w, int h) {
    long sum = 0;
    int n = 0;
    for (int i = 0; i < w * h; i++) {
      if (reddish(img[i])) {
        sum += i / w;
        n++;
      }
    }
    return n == 0 ? Double.NaN : (double) sum / n;
  }

  @Test
  void tiltingUpMovesTheBallDownInTheImage() {
    try (SimWorld world = room()) {
      SimRobot robot = world.addRobot("p3dx-sh");
      world
          .coloredObjects()
          .add(ColoredObject.cylinder("ball", 2000, 0, 250, 250, 0xD02020), false);
      SimCamera cam = SimCamera.onTop(world, robot);
      int w = cam.getWidth();
      int h = cam.getHeight();
      int[] img = new int[w * h];
      cam.setPanTilt(0, -15);
      cam.render(img);
      double low = redRow(img, w, h);
      cam.setPanTilt(0, -5);
      cam.render(img);
      double high = redRow(img, w, h);
      assertTrue(!Double.isNaN(low) && !Double.isNaN(high), "the ball is seen at both tilts");
      assertTrue(
          high > low + 5, "tilting up by 10 degrees moved the ball down: " + low + " -> " + high);
      assertEquals(-5, cam.getTilt(), 1e-9);
    }
  }

  @Test
  void wallsHideWhatIsBehindThem() {
    try (SimWorld world = room()) {
      SimRobot robot = world.addRobot("p3dx-sh");
      world
          .coloredObjects()
          .add(ColoredObject.cylinder("ball", 3000, 0, 250, 250, 0xD02020), false);
      world.injectObstacle(new ArLineSegment(1500, -1000, 1500, 1000));
      SimCamera cam = SimCamera.onTop(world, robot);
      int[] img = new int[cam.getWidth() * cam.getHeight()];
      cam.render(img);
      assertEquals(null, redColumns(img, cam.getWidth(), cam.getHeight()));
    }
  }

  @Test
  void movingAnObjectMovesItInTheImageAndSolidObjectsBlockSonar() {
    try (SimWorld world = room()) {
      SimRobot robot = world.addRobot("p3dx-sh");
      ColoredObject ball =
          world
              .coloredObjects()
              .add(ColoredObject.cylinder("ball", 2000, 0, 300, 300, 0xD02020), true);
      assertEquals(2000 - 150, world.castRay(0, 0, 0, 5000, robot), 2, "a solid ball stops rays");
      world.coloredObjects().move(ball.id(), 2000, -600);
      assertTrue(world.castRay(0, 0, 0, 5000, robot) > 4000, "moved out of the way");
      SimCamera cam = SimCamera.onTop(world, robot);
      int[] img = new int[cam.getWidth() * cam.getHeight()];
      cam.render(img);
      int[] cols = redColumns(img, cam.getWidth(), cam.getHeight());
      assertTrue(cols[0] > cam.getWidth() / 2, "to the right of the image");
    }
  }

  @Test
  void mapsDeclareColouredObjects() throws Exception {
    String text =
        "2D-Map\n"
            + "MapInfo: SectorType Name=RedBall \"Label=Red ball\" Sim.Color=0xD02020"
            + " Sim.Shape=cylinder Sim.Diameter=200 Sim.Height=200\n"
            + "MapInfo: SectorType Name=BlueBook Sim.Color=#2020C0 Sim.Height=50 Sim.Obstacle=yes\n"
            + "MapInfo: GoalType Name=Goal\n"
            + "Cairn: RedBall 3000 1500 0 \"\" ICON \"ball\"\n"
            + "Cairn: BlueBook 0 0 0 \"\" ICON \"book\" 1000 -100 1300 100\n"
            + "Cairn: Goal 10 10 0 \"\" ICON \"g\"\n"
            + "LINES\n-5000 -5000 5000 -5000\nDATA\n";
    ArMap map = ArMap.read(new StringReader(text), "test.map");
    try (SimWorld world = SimWorld.create(map, SimOptions.defaults())) {
      List<ColoredObject> objs = world.coloredObjects().list();
      assertEquals(2, objs.size());
      assertEquals("ball", objs.get(0).name());
      assertEquals(ColoredObject.Shape.CYLINDER, objs.get(0).shape());
      assertEquals(0x2020C0, objs.get(1).rgb());
      assertEquals(300, objs.get(1).width(), 1e-9);
      assertEquals(1000, world.castRay(0, 0, 0, 5000), 1e-6, "the book is solid");
    }
  }

  @Test
  void badColourIsReported() {
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> ColoredObjects.parseColor("reddish"));
    assertTrue(e.getMessage().contains("0xRRGGBB"));
  }
}
