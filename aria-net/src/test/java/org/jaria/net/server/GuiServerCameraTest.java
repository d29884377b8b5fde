package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.data.CameraInfo;
import org.jaria.net.guiserver.GuiServer;
import org.jaria.ptz.ArVCC4;
import org.junit.jupiter.api.Test;

/**
 * The pan-tilt-zoom camera as ARIA's clients command it: listed by {@code getCameraList}, its
 * ranges and position in ArNetworking's "double" layout, absolute and relative moves, the modes,
 * and ArNetworking's older integer requests.
 */
class GuiServerCameraTest {

  /**
   * The real VC-C4 driver with its frames dropped, recording every pan and tilt it was asked to go
   * to (after clamping to its limits).
   */
  static final class FakeVcc4 extends ArVCC4 {
    final java.util.List<double[]> history = new java.util.concurrent.CopyOnWriteArrayList<>();

    FakeVcc4() {
      super(frame -> {});
    }

    @Override
    protected boolean panTiltClamped(double p, double t) {
      history.add(new double[] {p, t});
      return super.panTiltClamped(p, t);
    }
  }

  private static ArNetPacket call(GuiRig rig, String name, ArNetPacket args) throws Exception {
    return rig.await(rig.client.requestOnce(name, args));
  }

  private static ArNetPacket byte2s(int... v) {
    ArNetPacket p = new ArNetPacket();
    for (int x : v) {
      p.byte2ToBuf(x);
    }
    return p;
  }

  @Test
  void theCameraIsListedWithItsRequests() throws Exception {
    FakeVcc4 cam = new FakeVcc4();
    try (GuiRig rig = GuiRig.plain(b -> b.ptz(cam))) {
      List<CameraInfo> list = CameraInfo.readList(rig.call("getCameraList"));
      assertEquals(1, list.size());
      CameraInfo c = list.get(0);
      assertEquals("Cam1", c.name());
      assertEquals("VCC4", c.type());
      assertEquals("Camera", c.displayName());
      // In name order, as ARIA's collection keeps them; setCameraPct is not offered (no FOV).
      assertEquals(
          List.of(
              "cameraModeUpdated",
              "getCameraData",
              "getCameraDataInt",
              "getCameraInfo",
              "getCameraInfoInt",
              "getCameraModeList",
              "resetCamera",
              "setCameraAbs",
              "setCameraAbsInt",
              "setCameraMode",
              "setCameraPctInt",
              "setCameraRel",
              "setCameraRelInt"),
          c.commands().stream().map(CameraInfo.Command::command).toList());
      CameraInfo.Command data = c.commands().get(1);
      assertEquals("getCameraDataCam1", data.requestName());
      assertEquals(100, data.requestInterval());
      assertEquals("cameraUpdate", c.commands().get(2).requestName(), "older ones unsuffixed");
      for (CameraInfo.Command k : c.commands()) {
        assertTrue(rig.gui.getServer().dataExists(k.requestName()), k.requestName());
      }
      assertFalse(rig.gui.getServer().dataExists("setCameraPctCam1"));
    }
  }

  @Test
  void ptzCameraClientExamplesArithmeticPansToTheLimitsAndBack() throws Exception {
    FakeVcc4 cam = new FakeVcc4();
    try (GuiRig rig = GuiRig.plain(b -> b.ptz(cam))) {
      ArNetPacket info = rig.call("getCameraInfoCam1");
      // The example reads the ranges dividing by 1000 (the server multiplied by 100) ...
      double minPan = info.bufToByte2() / 1000.0;
      double maxPan = info.bufToByte2() / 1000.0;
      double minTilt = info.bufToByte2() / 1000.0;
      double maxTilt = info.bufToByte2() / 1000.0;
      assertEquals(0, info.bufToByte2());
      assertEquals(10000, info.bufToByte2());
      assertEquals(1, info.bufToByte());
      assertEquals(-9.8, minPan, 1e-9);
      // ... and multiplies by 1000 when it asks for a position: the two slips cancel out.
      double[][] stages = {{minPan, 0}, {maxPan, 0}, {0, 0}, {0, minTilt}, {0, maxTilt}};
      double[][] want = {{-98, 0}, {98, 0}, {0, 0}, {0, -30}, {0, 88}};
      for (int i = 0; i < stages.length; i++) {
        call(
            rig,
            "setCameraAbsCam1",
            byte2s((short) (stages[i][0] * 1000), (short) (stages[i][1] * 1000)));
        assertEquals(want[i][0], cam.getPan(), 1e-9, "stage " + i);
        assertEquals(want[i][1], cam.getTilt(), 1e-9, "stage " + i);
      }
      ArNetPacket data = rig.call("getCameraDataCam1");
      assertEquals(0, data.bufToByte2());
      assertEquals(8800, data.bufToByte2());
      assertEquals(0, data.bufToByte2(), "the example sends no zoom: zoom 0, as ARIA");
    }
  }

  @Test
  void relativeMovesModesAndTheOlderIntegerRequests() throws Exception {
    FakeVcc4 cam = new FakeVcc4();
    try (GuiRig rig = GuiRig.plain(b -> b.ptz(cam))) {
      call(rig, "setCameraAbsCam1", byte2s(1000, 500, 5000)); // 10°, 5°, zoom 50 %
      assertEquals(980, cam.getZoom());
      call(rig, "setCameraRelCam1", byte2s(1000, 0, 0));
      // At half zoom a relative move is halved (ARIA's rule), rounded away from zero.
      assertEquals(15, cam.getPan(), 1e-9);
      ArNetPacket modes = rig.call("getCameraModeListCam1");
      assertEquals(2, modes.bufToUByte2());
      assertEquals("Position", modes.bufToStr());
      assertEquals("LookAtPoint", modes.bufToStr());
      ArNetPacket look = new ArNetPacket();
      org.jaria.geom.ArPose point =
          new org.jaria.geom.ArPose(rig.robot.getX() + 2000, rig.robot.getY() - 3000);
      look.strToBuf("LookAtPoint").byte4ToBuf((int) point.x()).byte4ToBuf((int) point.y());
      call(rig, "setCameraModeCam1", look);
      rig.run(300);
      assertEquals("LookAtPoint", rig.call("cameraModeUpdatedCam1").bufToStr());
      org.jaria.geom.ArPose me = rig.robot.getPose();
      double want =
          Math.max(
              -98, Math.min(98, -org.jaria.geom.ArMath.subAngle(me.findAngleTo(point), me.th())));
      assertEquals(want, cam.getPan(), 1, "faces the point");
      rig.call("resetCamera" + GuiServer.CAMERA_NAME);
      assertEquals(0, cam.getPan(), 1e-9);
      assertEquals("Position", rig.gui.getCameraHandler().getMode());
      ArNetPacket abs = new ArNetPacket();
      abs.byteToBuf(-20).byteToBuf(10).byteToBuf(0);
      call(rig, "cameraAbs", abs);
      ArNetPacket upd = rig.call("cameraUpdate");
      assertEquals(-20, upd.bufToByte2());
      assertEquals(10, upd.bufToByte2());
      ArNetPacket old = rig.call("cameraInfo");
      assertEquals(-98, old.bufToByte2());
      assertEquals(98, old.bufToByte2());
    }
  }

  @Test
  void aClientsPanToTheRightTurnsTheSimulatedCameraRight() throws Exception {
    // The whole chain with one sign (ARIA's, pan positive to the right): the client's request, the
    // camera handler, the VC-C4 driver's frames through the robot's AUX port, the simulator's VC-C4
    // and the simulated camera that follows it.
    ArVCC4[] vcc4 = new ArVCC4[1];
    try (GuiRig rig =
        new GuiRig(
            (sim, b) -> {
              vcc4[0] = new ArVCC4(sim.robot());
              vcc4[0].init();
              b.ptz(vcc4[0]);
              return null;
            },
            b -> b)) {
      org.jaria.sim.camera.SimCamera view =
          org.jaria.sim.camera.SimCamera.onTop(rig.sim.world(), rig.sim.sim());
      view.setFollowAuxPtz(true);
      call(rig, "setCameraAbsCam1", byte2s(3000, -1000)); // 30° right, 10° down
      rig.run(2000); // the driver paces its frames 300 ms apart
      assertEquals(30, vcc4[0].getPan(), 1e-9);
      assertEquals(30, rig.sim.sim().getPtzPointing().panRightDeg(), 0.1, "the head turned right");
      assertEquals(-10, rig.sim.sim().getPtzPointing().tiltUpDeg(), 0.1);
      assertEquals(
          rig.sim.sim().getTruePose().th() - 30,
          view.getViewPose().th(),
          0.1,
          "the camera looks 30° right of the robot's heading");
      assertEquals(3000, rig.call("getCameraDataCam1").bufToByte2(), "and says so to clients");
    }
  }
}
