package org.jaria.system;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.time.Duration;
import org.jaria.action.ArActionConstantVelocity;
import org.jaria.action.ArActionKeydrive;
import org.jaria.action.ArActionLimiterForwards;
import org.jaria.acts.ArACTS_1_2;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.server.ActsLink;
import org.jaria.acts.server.VisionPipeline;
import org.jaria.connection.PipeConnection;
import org.jaria.input.ArKeyHandler;
import org.jaria.robot.ArRobot;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import org.jaria.simvision.ChaseScene;
import org.jaria.simvision.SimCameraPtz;
import org.jaria.simvision.SimCameraSource;
import org.jaria.tools.examples.ActsColorFollowingExample;
import org.jaria.tools.examples.Chase;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The vision-control application end to end on virtual time: simulated camera, ACTS blob tracking
 * and its wire protocol (over an in-memory pipe), ArACTS_1_2 in the robot's cycle, and the thesis's
 * Chase action driving the simulated robot.
 */
class ChaseScenarioTest {

  private SimWorld world;
  private ChaseScene scene;
  private SimulatedRobot sim;
  private ArRobot robot;
  private Chase chase;
  private final ArKeyHandler keys = new ArKeyHandler();
  private ArActionKeydrive keydrive;

  @BeforeEach
  void setUp() throws IOException {
    world = SimWorld.bundled("hall", SimOptions.builder().seed(11).build());
    SimRobot r = world.addRobot("p3dx-sh");
    scene = new ChaseScene(world, r, 2500, 400);
    // ACTS answers on one end of a pipe; the robot's ArACTS_1_2 talks on the other.
    PipeConnection.Pair pipe = PipeConnection.pair(world.getClock(), "acts");
    pipe.b().open();
    ActsLink link =
        new ActsLink(
            new VisionPipeline(
                new SimCameraSource(scene.camera), scene.bank, TrackerSettings.DEFAULT),
            pipe.b());
    world.addStepListener(
        () -> {
          try {
            link.pump();
          } catch (IOException e) {
            throw new UncheckedIOException(e);
          }
        });
    sim = SimulatedRobot.connect(world, r);
    robot = sim.robot();
    ArACTS_1_2 acts = new ArACTS_1_2(world.getClock());
    acts.setReadTimeouts(0, 0); // lockstep: never wait for the reply, it comes next tick
    assertTrue(acts.openPort(robot, pipe.a()), acts.getOpenMessage());
    chase = new Chase(acts, new SimCameraPtz(scene.camera));
    robot.addAction(new ArActionLimiterForwards("speed limiter near", 350, 800, 200), 7);
    // As in the thesis: keyboard driving at priority 4, off until 'a' is pressed.
    keydrive = new ArActionKeydrive(keys);
    keys.addKeyHandler('a', () -> ActsColorFollowingExample.toggleAction(keydrive));
    keys.attachKeyHandler(robot, false, null);
    robot.addAction(keydrive, 4);
    keydrive.deactivate();
    robot.addAction(chase, 3);
    robot.addAction(new ArActionConstantVelocity("stop", 0), 1);
    robot.enableMotors();
  }

  @AfterEach
  void tearDown() {
    keys.close();
    sim.close();
    world.close();
  }

  @Test
  void robotDrivesUpToTheBallAndKeepsFollowingItAsItMoves() {
    assertTrue(
        sim.runUntil(() -> chase.getState() == Chase.State.TARGET, Duration.ofSeconds(3)),
        "the ball is seen");
    assertTrue(
        sim.runUntil(() -> scene.distanceToBall() < 900, Duration.ofSeconds(30)),
        "the robot reaches the ball; still " + scene.distanceToBall() + " mm away");
    // Now the ball rolls sideways, 2 m to the robot's left, at 100 mm/s.
    double x = scene.ball().x();
    double y = scene.ball().y();
    double heading = Math.toRadians(scene.robot.getTruePose().th());
    org.jaria.geom.ArPose before = scene.robot.getTruePose();
    for (int step = 1; step <= 100; step++) {
      double d = 20.0 * step;
      scene.moveBall(x - d * Math.sin(heading), y + d * Math.cos(heading));
      sim.runMillis(200);
      assertTrue(
          scene.distanceToBall() < 1200,
          "keeps up with the ball at step " + step + ": " + scene.distanceToBall() + " mm");
    }
    double moved = scene.robot.getTruePose().findDistanceTo(before);
    assertTrue(moved > 1500, "the robot went along with the ball: " + moved + " mm");
  }

  @Test
  void lostTargetStopsTheRobotAfterTheTimeout() {
    assertTrue(sim.runUntil(() -> robot.getVel() > 100, Duration.ofSeconds(10)), "chasing");
    scene.removeBall();
    sim.runMillis(500);
    assertEquals(Chase.State.TARGET, chase.getState(), "a moment without the ball is not a loss");
    assertTrue(
        sim.runUntil(() -> chase.getState() == Chase.State.NO_TARGET, Duration.ofSeconds(3)),
        "lost after a second without blobs");
    sim.runMillis(3000);
    assertEquals(0, robot.getVel(), 5, "the stop action has the robot");
  }

  @Test
  void keyAHandsTheRobotToTheKeyboardAndBack() {
    scene.removeBall();
    sim.runMillis(3000);
    assertEquals(0, robot.getVel(), 5, "no ball: the stop action holds the robot");
    keys.feedKey('a');
    sim.runMillis(100);
    assertTrue(keydrive.isActive(), "'a' switched keyboard driving on");
    for (int i = 0; i < 8; i++) {
      keys.feedKey(ArKeyHandler.UP);
      sim.runMillis(100);
    }
    sim.runMillis(2000);
    assertTrue(robot.getVel() > 100, "the arrow keys drive: " + robot.getVel() + " mm/s");
    keys.feedKey('a');
    sim.runMillis(3000);
    assertTrue(!keydrive.isActive(), "'a' switched it off again");
    assertEquals(0, robot.getVel(), 5, "back to the chase, which has no ball: stopped");
  }
}
