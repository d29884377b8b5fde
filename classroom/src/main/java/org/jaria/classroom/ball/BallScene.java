package org.jaria.classroom.ball;

import java.io.IOException;
import java.io.UncheckedIOException;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.color.Trainer;
import org.jaria.acts.image.RgbImage;
import org.jaria.acts.server.ActsLink;
import org.jaria.acts.server.VisionPipeline;
import org.jaria.connection.PipeConnection;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.camera.ColoredObject;
import org.jaria.sim.camera.SimCamera;
import org.jaria.simvision.SimCameraSource;

/**
 * The ball-following world: the hall, a robot with a camera, a red ball ahead of it, ACTS channel 1
 * trained on the ball's red, and an ACTS server whose pipe the robot link carries to the student's
 * ArACTS_1_2, all in lockstep on the world's virtual clock.
 */
final class BallScene implements AutoCloseable {

  static final int BALL_RED = 0xC81E1E;
  static final double BALL_DIAMETER = 250;

  final SimWorld world;
  final SimRobot simRobot;

  /** The grader's end of the ACTS server's pipe: the student's ACTS client is at the other. */
  final PipeConnection actsEnd;

  final double startDistance;
  private ColoredObject ball;

  /** The scene, with the ball {@code ahead} mm in front of the robot and {@code left} mm left. */
  BallScene(long seed, double ahead, double left) {
    world = SimWorld.bundled("hall", SimOptions.builder().seed(seed).build());
    try {
      simRobot = world.addRobot("p3dx-sh");
      SimCamera camera = SimCamera.onTop(world, simRobot);
      camera.setPanTilt(0, -10);
      ArPose p = simRobot.getTruePose();
      double r = Math.toRadians(p.th());
      ball =
          world
              .coloredObjects()
              .add(
                  ColoredObject.cylinder(
                      "ball",
                      p.x() + ahead * Math.cos(r) - left * Math.sin(r),
                      p.y() + ahead * Math.sin(r) + left * Math.cos(r),
                      BALL_DIAMETER,
                      BALL_DIAMETER,
                      BALL_RED),
                  true);
      ChannelBank bank = new ChannelBank();
      trainRed(bank, camera);
      PipeConnection.Pair pipe = PipeConnection.pair(world.getClock(), "acts");
      pipe.b().open();
      ActsLink link =
          new ActsLink(
              new VisionPipeline(new SimCameraSource(camera), bank, TrackerSettings.DEFAULT),
              pipe.b());
      world.addStepListener(
          () -> {
            try {
              link.pump();
            } catch (IOException e) {
              throw new UncheckedIOException(e);
            }
          });
      actsEnd = pipe.a();
      actsEnd.open();
      startDistance = distanceToBall();
    } catch (IOException e) {
      world.close();
      throw new UncheckedIOException(e);
    } catch (RuntimeException e) {
      world.close();
      throw e;
    }
  }

  /** Distance from the robot's true centre to the ball's edge, mm. */
  double distanceToBall() {
    ArPose p = simRobot.getTruePose();
    return Math.hypot(ball.x() - p.x(), ball.y() - p.y()) - BALL_DIAMETER / 2;
  }

  ColoredObject ball() {
    return ball;
  }

  void moveBall(double x, double y) {
    ball = world.coloredObjects().move(ball.id(), x, y);
  }

  void removeBall() {
    world.coloredObjects().remove(ball.id());
  }

  /** Channel 1 learns the clearly red pixels the camera sees, as a person would in EZ-Train. */
  private static void trainRed(ChannelBank bank, SimCamera camera) {
    RgbImage frame = new RgbImage(camera.getWidth(), camera.getHeight());
    camera.render(frame.pixels());
    int minX = Integer.MAX_VALUE;
    int minY = Integer.MAX_VALUE;
    int maxX = -1;
    int maxY = -1;
    for (int y = 0; y < frame.height(); y++) {
      for (int x = 0; x < frame.width(); x++) {
        int px = frame.get(x, y);
        int red = (px >> 16) & 0xFF;
        if (red > 90 && red > 2 * ((px >> 8) & 0xFF) && red > 2 * (px & 0xFF)) {
          minX = Math.min(minX, x);
          maxX = Math.max(maxX, x);
          minY = Math.min(minY, y);
          maxY = Math.max(maxY, y);
        }
      }
    }
    if (maxX < 0) {
      throw new IllegalStateException("the camera does not see the ball to train on it");
    }
    Trainer t = new Trainer(bank);
    t.setChannel(1);
    int qx = (maxX - minX) / 4;
    int qy = (maxY - minY) / 4;
    t.addRect(frame, minX + qx, minY + qy, maxX - qx, maxY - qy);
  }

  @Override
  public void close() {
    actsEnd.close();
    world.close();
  }
}
