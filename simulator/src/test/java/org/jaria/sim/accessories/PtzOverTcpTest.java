package org.jaria.sim.accessories;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.jaria.clock.Clock;
import org.jaria.connection.ArTcpConnection;
import org.jaria.ptz.ArDPPTU;
import org.jaria.ptz.ArSonyPTZ;
import org.jaria.robot.ArRobot;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.camera.SimCamera;
import org.jaria.sim.client.SimulatedRobot;
import org.jaria.sim.serial.PtzHead;
import org.junit.jupiter.api.Test;

/**
 * ArSonyPTZ and ArDPPTU driving the simulator's Sony and Directed Perception units through a real
 * TCP connection, as {@code jaria sim --ptz-type sony|dpptu} serves them: commands out as TTY2,
 * answers back as SERAUXpacs, and the simulated camera turning with the head.
 */
class PtzOverTcpTest {

  private static SimWorld world(String ptzType) throws IOException {
    SimWorld w = SimWorld.empty(SimOptions.builder().basePort(0).watchdogMillis(0).build());
    w.addRobot(RobotOptions.of("p3dx-sh").withPtzType(ptzType).withPort(0));
    w.listen();
    w.startRealTime(4);
    return w;
  }

  private static ArRobot connect(SimWorld w) {
    ArRobot robot = new ArRobot("ptz-client");
    robot.setParamsDirectory(null);
    robot.setDeviceConnection(
        new ArTcpConnection("127.0.0.1", w.getRobot(0).getPort(), Clock.system()));
    assertTrue(robot.blockingConnect(), robot.getConnectFailure());
    robot.runAsync(true);
    return robot;
  }

  /** Waits (on the world's steps, never on a timer) until {@code cond} holds; 20 s at most. */
  private static void await(SimWorld w, BooleanSupplier cond, String what)
      throws InterruptedException {
    CountDownLatch latch = new CountDownLatch(1);
    Runnable check =
        () -> {
          if (cond.getAsBoolean()) {
            latch.countDown();
          }
        };
    w.addStepListener(check);
    try {
      assertTrue(latch.await(20, TimeUnit.SECONDS), what);
    } finally {
      w.removeStepListener(check);
    }
  }

  @Test
  void sonyCameraPansTiltsZoomsAnswersAndTheCameraFollows() throws Exception {
    try (SimWorld w = world("sony")) {
      SimRobot sim = w.getRobot(0);
      assertEquals("sony", sim.getAuxDeviceName());
      SimCamera camera = SimCamera.onTop(w, sim);
      camera.setFollowAuxPtz(true);
      ArRobot robot = connect(w);
      try {
        // tag::sony[]
        ArSonyPTZ ptz = new ArSonyPTZ(robot); // a Sony EVI-D30 on the robot's AUX1 port
        assertTrue(ptz.init()); // VISCA broadcasts, then pan 0, tilt 0, zoom 0
        // end::sony[]
        // init: two broadcasts back, then pan-tilt and zoom each acknowledged and completed
        await(w, () -> ptz.getCompletionCount() == 2 && ptz.getRepliesOutstanding() == 0, "init");
        assertEquals(2, ptz.getAckCount());

        assertTrue(ptz.panTilt(30, -10));
        assertTrue(ptz.zoom(512));
        await(w, () -> ptz.getCompletionCount() == 4, "pan-tilt and zoom done");
        PtzHead.Pointing p = sim.getPtzPointing();
        assertEquals(30, p.panRightDeg(), 0.06, "the head turned right 30°");
        assertEquals(-10, p.tiltUpDeg(), 0.06);

        // tag::inquiry[]
        // inquiries out through TTY2; the answers come back through GETAUX / SERAUXpac and fill
        // getReportedPan(), getReportedTilt() and getReportedZoom() a few cycles later
        assertTrue(ptz.requestPosition());
        // end::inquiry[]
        await(w, () -> ptz.getReportedZoom() == 512, "position answers");
        assertEquals(30, ptz.getReportedPan(), 0.06);
        assertEquals(-10, ptz.getReportedTilt(), 0.06);
        assertEquals(0, ptz.getErrorCount());
        assertNull(ptz.getLastError());

        // the simulated camera looks 30° to the right of the robot's heading (ARIA's sign)
        assertEquals(30, camera.getPan(), 0.06);
        double heading = sim.getTruePose().th();
        assertEquals(heading - 30, camera.getViewPose().th(), 0.06);
        assertEquals(512 * SimCamera.MAX_ZOOM / 1023.0, camera.getZoom(), 1);

        assertTrue(ptz.panTilt(-200, 40)); // clamped to −95°, +25°
        assertTrue(ptz.requestPosition());
        await(w, () -> ptz.getReportedPan() < -90, "clamped pan reported");
        assertEquals(-95, ptz.getReportedPan(), 0.06);
        assertEquals(25, ptz.getReportedTilt(), 0.06);
        assertEquals(-95, camera.getPan(), 0.06);
      } finally {
        robot.stopRunning();
        robot.disconnect();
      }
    }
  }

  @Test
  void directedPerceptionUnitMovesAndReportsItsPosition() throws Exception {
    try (SimWorld w = world("dpptu")) {
      SimRobot sim = w.getRobot(0);
      SimCamera camera = SimCamera.onTop(w, sim);
      camera.setFollowAuxPtz(true);
      ArRobot robot = connect(w);
      try {
        ArDPPTU ptu = new ArDPPTU(robot);
        assertTrue(ptu.init()); // I, PP0, TP0
        await(w, () -> ptu.getDoneCount() == 3, "init answered");

        assertTrue(ptu.panTilt(-45, 20));
        assertTrue(ptu.panSlew(30));
        assertTrue(ptu.requestPosition());
        await(w, () -> ptu.canGetRealPanTilt() && ptu.getReportedTilt() > 0, "PP/TP answers");
        // −45° is −875 steps: the answer is longer than the shortest, and is fetched whole
        assertEquals(-875 * 0.0514, ptu.getReportedPan(), 1e-6);
        assertEquals(389 * 0.0514, ptu.getReportedTilt(), 1e-6);
        assertEquals(6, ptu.getDoneCount(), "I, PP0, TP0, PP-875, TP389, PS584");
        assertEquals(0, ptu.getErrorCount());
        assertEquals(-45, sim.getPtzPointing().panRightDeg(), 0.05);
        assertEquals(-45, camera.getPan(), 0.05, "the camera looks 45° left");
        assertEquals(0, ptu.getRepliesOutstanding());
      } finally {
        robot.stopRunning();
        robot.disconnect();
      }
    }
  }

  @Test
  void withNothingOnTheAuxPortTheDriverStopsAskingForAnswers() {
    try (SimWorld w = SimWorld.empty(SimOptions.builder().watchdogMillis(0).build())) {
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withPtzType("none"));
      try (SimulatedRobot sim = SimulatedRobot.connect(w, r)) {
        ArSonyPTZ ptz = new ArSonyPTZ(sim.robot());
        assertTrue(ptz.init());
        assertTrue(ptz.requestPosition());
        assertTrue(
            sim.runUntil(() -> ptz.getRepliesOutstanding() == 0, Duration.ofSeconds(5)),
            "an empty SERAUXpac means nothing is attached");
        sim.runMillis(1000);
        assertEquals(0, ptz.getReplyBytes());
        assertFalse(ptz.canGetRealPanTilt());
        assertNull(r.getPtzPointing());
      }
    }
  }
}
