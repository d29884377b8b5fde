package org.jaria.simvision;

import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.image.RgbImage;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.camera.ColoredObject;
import org.jaria.sim.camera.SimCamera;

/**
 * The scene of the vision-control application on the simulator: a red ball on the floor in front of
 * the robot, a camera on the robot, and ACTS channel 1 trained on the ball's red as a person would
 * in EZ-Train.
 */
public final class ChaseScene {

  /** The ball's colour. */
  public static final int BALL_RED = 0xC81E1E;

  /** The ball's diameter, mm. */
  public static final double BALL_DIAMETER = 250;

  public final SimWorld world;
  public final SimRobot robot;
  public final SimCamera camera;
  public final ChannelBank bank = new ChannelBank();
  private ColoredObject ball;

  /**
   * Sets the scene: a solid red ball {@code ahead} mm in front of the robot (and {@code left} mm to
   * its left), a camera on the robot, channel 1 trained on the ball.
   *
   * @throws IllegalStateException if the camera cannot see the ball to train on it
   */
  public ChaseScene(SimWorld world, SimRobot robot, double ahead, double left) {
    this.world = world;
    this.robot = robot;
    this.camera = SimCamera.onTop(world, robot);
    camera.setPanTilt(0, -10);
    ArPose p = robot.getTruePose();
    double r = Math.toRadians(p.th());
    double x = p.x() + ahead * Math.cos(r) - left * Math.sin(r);
    double y = p.y() + ahead * Math.sin(r) + left * Math.cos(r);
    ball =
        world
            .coloredObjects()
            .add(
                ColoredObject.cylinder("ball", x, y, BALL_DIAMETER, BALL_DIAMETER, BALL_RED), true);
    RgbImage frame = new RgbImage(camera.getWidth(), camera.getHeight());
    camera.render(frame.pixels());
    if (ColorTraining.trainRed(bank, 1, frame) == 0) {
      throw new IllegalStateException("the camera does not see the ball to train on it");
    }
  }

  /** The ball now. */
  public ColoredObject ball() {
    return ball;
  }

  /** Moves the ball to (x, y). */
  public void moveBall(double x, double y) {
    ball = world.coloredObjects().move(ball.id(), x, y);
  }

  /** Takes the ball out of the world (the target is lost). */
  public void removeBall() {
    world.coloredObjects().remove(ball.id());
  }

  /** Distance from the robot's true centre to the ball's edge, mm. */
  public double distanceToBall() {
    ArPose p = robot.getTruePose();
    return Math.hypot(ball.x() - p.x(), ball.y() - p.y()) - BALL_DIAMETER / 2;
  }
}
