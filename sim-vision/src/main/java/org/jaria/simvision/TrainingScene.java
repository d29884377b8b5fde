package org.jaria.simvision;

import java.io.IOException;
import org.jaria.acts.image.ImageSource;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.camera.ColoredObject;
import org.jaria.sim.camera.SimCamera;

/**
 * A simulated world to train colours on with the simulator's camera (EZ-Train's File → Simulator
 * Camera): the hall, a P3-DX at its home with a camera on top, and four coloured things in front of
 * it on the floor — a red ball (the one {@link ChaseScene} chases), a green box, a blue can and a
 * yellow box — the simulator's version of the tutorial's desk scene.
 *
 * <p>The objects are seen by cameras only (robots pass through them), so they never stop a program
 * that drives the robot around to look at them from elsewhere.
 */
public final class TrainingScene implements AutoCloseable {

  /** The red ball's colour (the same red as {@link ChaseScene#BALL_RED}). */
  public static final int RED = ChaseScene.BALL_RED;

  /** The green box's colour. */
  public static final int GREEN = 0x2E9A3A;

  /** The blue can's colour. */
  public static final int BLUE = 0x2A4FC8;

  /** The yellow box's colour. */
  public static final int YELLOW = 0xE8C830;

  /** Camera tilt, degrees: looking down a little at the floor in front of the robot. */
  public static final double TILT = -12;

  private final SimWorld world;
  private final SimRobot robot;

  private TrainingScene(SimWorld world) {
    this.world = world;
    this.robot = world.addRobot("p3dx-sh");
    var objects = world.coloredObjects();
    objects.add(ColoredObject.cylinder("red ball", 4000, 7650, 250, 250, RED), false);
    objects.add(ColoredObject.box("green box", 4300, 7050, 20, 400, 300, 350, GREEN), false);
    objects.add(ColoredObject.cylinder("blue can", 3500, 7250, 150, 300, BLUE), false);
    objects.add(ColoredObject.box("yellow box", 3800, 8150, -15, 300, 300, 200, YELLOW), false);
  }

  /**
   * Builds the scene (not running, not listening).
   *
   * @param port the TCP port the robot will listen on after {@link #listen()} (0: any free port)
   */
  public static TrainingScene create(int port) {
    SimWorld w = SimWorld.bundled("hall", SimOptions.builder().seed(1).basePort(port).build());
    try {
      return new TrainingScene(w);
    } catch (RuntimeException e) {
      w.close();
      throw e;
    }
  }

  /** The world. */
  public SimWorld world() {
    return world;
  }

  /** The robot carrying the camera. */
  public SimRobot robot() {
    return robot;
  }

  /**
   * Opens the robot's TCP port, so an ARIA program can drive it while the camera shows what it
   * sees.
   *
   * @return the port
   * @throws IOException if the port is taken (the message says which)
   */
  public int listen() throws IOException {
    world.listen();
    return robot.getPort();
  }

  /** Runs the world in real time on its own thread. */
  public void start() {
    world.startRealTime(1);
  }

  /**
   * A camera of {@code width} × {@code height} pixels on the robot, tilted down at the objects.
   * Closing the source leaves the world alone.
   */
  public ImageSource camera(int width, int height) {
    SimCamera c = new SimCamera(world, robot, width, height, 100, 450);
    c.setPanTilt(0, TILT);
    return new SimCameraSource(c);
  }

  /** Stops the world and closes its port. */
  @Override
  public void close() {
    world.close();
  }
}
