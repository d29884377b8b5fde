package org.jaria.simvision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.acts.color.Channel;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.image.ImageSource;
import org.jaria.acts.image.RgbImage;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;

/**
 * The simulator's camera as ACTS sees it: the training scene's camera shows its four coloured
 * things, the chase scene trains channel 1 on the ball's red and on nothing else, and a picture
 * with no red trains nothing.
 */
class SimVisionTest {

  /** Pixels of {@code image} within {@code tolerance} of {@code rgb} in each component. */
  private static int near(RgbImage image, int rgb, int tolerance) {
    int n = 0;
    for (int p : image.pixels()) {
      boolean close = true;
      for (int shift = 0; shift <= 16; shift += 8) {
        close &= Math.abs(((p >> shift) & 0xFF) - ((rgb >> shift) & 0xFF)) <= tolerance;
      }
      if (close) {
        n++;
      }
    }
    return n;
  }

  @Test
  void theTrainingSceneCameraShowsItsFourColouredThings() throws Exception {
    try (TrainingScene scene = TrainingScene.create(0)) {
      ImageSource camera = scene.camera(320, 240);
      assertEquals(320, camera.width());
      assertEquals(240, camera.height());
      RgbImage frame = new RgbImage(camera.width(), camera.height());
      assertTrue(camera.nextFrame(frame.pixels()));
      for (int colour :
          new int[] {
            TrainingScene.RED, TrainingScene.GREEN, TrainingScene.BLUE, TrainingScene.YELLOW
          }) {
        assertTrue(near(frame, colour, 60) > 20, String.format("%06X in view", colour));
      }
    }
  }

  /** Pixels of the camera's view that {@code channel} classifies. */
  private static int classified(ChaseScene scene, Channel channel) {
    RgbImage frame = new RgbImage(scene.camera.getWidth(), scene.camera.getHeight());
    new SimCameraSource(scene.camera).nextFrame(frame.pixels());
    int n = 0;
    for (int p : frame.pixels()) {
      if (channel.classifies(p)) {
        n++;
      }
    }
    return n;
  }

  @Test
  void theChaseSceneTrainsChannelOneOnTheBallOnly() {
    try (SimWorld world = SimWorld.bundled("hall", SimOptions.builder().seed(1).build())) {
      SimRobot robot = world.addRobot("p3dx-sh");
      ChaseScene scene = new ChaseScene(world, robot, 2500, 0);
      Channel one = scene.bank.copyOf(1);
      assertTrue(scene.distanceToBall() > 2000 && scene.distanceToBall() < 2500);
      int withBall = classified(scene, one);
      assertTrue(withBall > 20, "the ball's pixels are in channel 1: " + withBall);
      scene.removeBall();
      assertEquals(0, classified(scene, one), "nothing else in view is");
    }
  }

  @Test
  void aPictureWithNothingRedTrainsNothing() {
    RgbImage grey = new RgbImage(40, 30);
    java.util.Arrays.fill(grey.pixels(), 0x808080);
    ChannelBank bank = new ChannelBank();
    assertEquals(0, ColorTraining.trainRed(bank, 2, grey));
    assertFalse(bank.copyOf(2).classifies(ChaseScene.BALL_RED));
  }
}
