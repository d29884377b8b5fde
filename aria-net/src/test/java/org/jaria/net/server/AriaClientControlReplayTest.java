package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.PeerRecording;
import org.jaria.net.RawClient;
import org.jaria.net.data.CameraInfo;
import org.jaria.net.data.DataInfo;
import org.jaria.net.protocol.Protocol;
import org.jaria.net.server.modes.ArServerModes;
import org.junit.jupiter.api.Test;

/**
 * Replays what ARIA 2.9.1's clients sent to {@code jaria demo guiserver} when they drive, point the
 * camera and change the map (recorded by hand, see docs/networking.md), and what serverDemo lists
 * for its camera.
 */
class AriaClientControlReplayTest {

  /** Reads packets until one of {@code command}, advancing the robot while it has work waiting. */
  private static ArNetPacket readStepping(GuiRig rig, RawClient aria, int command)
      throws Exception {
    return readStepping(rig, aria, command, -1).get(command);
  }

  /**
   * Reads packets until one of {@code command} and one of {@code other} (-1: none) have come, in
   * either order (two workers may answer one client's requests in either order), advancing the
   * robot while it has work waiting; the first of each by command.
   */
  static Map<Integer, ArNetPacket> readStepping(GuiRig rig, RawClient aria, int command, int other)
      throws Exception {
    Map<Integer, ArNetPacket> got = new java.util.HashMap<>();
    long end = System.nanoTime() + Eventually.LIMIT.toNanos();
    while (System.nanoTime() < end) {
      if (rig.gui.getServer().getPendingCycleCommands() > 0) {
        rig.sim.world().step();
      }
      while (aria.available() > 0) {
        ArNetPacket p = aria.read();
        if (p.getCommand() == command || p.getCommand() == other) {
          got.putIfAbsent(p.getCommand(), p);
          if (got.containsKey(command) && (other < 0 || got.containsKey(other))) {
            return got;
          }
        }
        if (p.getCommand() == Protocol.FIRST_DATA_COMMAND) {
          throw new AssertionError(
              "requestFailed: " + p.bufToStr() + ": " + p.bufToStr() + " (" + p.bufToByte2() + ")");
        }
      }
      java.util.concurrent.locks.LockSupport.parkNanos(200_000);
    }
    throw new AssertionError("no packet " + command + " within " + Eventually.LIMIT);
  }

  @Test
  void clientDemoDrivingAtItsOwnRateStopsAtOnceOnSpace() throws Exception {
    byte[] c2s = PeerRecording.bytes("clientDemo-stop.c2s.bin");
    byte[] s2c = PeerRecording.bytes("clientDemo-stop.s2c.bin");
    Map<Integer, String> then = PeerRecording.listedCommands(PeerRecording.packets(s2c));
    List<ArNetPacket> sent = PeerRecording.packets(c2s);
    // By hand: Up for six seconds (the table showed 750 mm/s), then Space, then Esc.
    List<String> names = new ArrayList<>();
    for (ArNetPacket p : sent) {
      names.add(then.getOrDefault(p.getCommand(), Integer.toString(p.getCommand())));
    }
    int drives = (int) names.stream().filter("ratioDrive"::equals).count();
    assertTrue(drives > 3000, drives + " ratioDrive in six seconds");
    assertEquals("stop", names.get(names.size() - 2), "then one stop, then goodbye");
    // Its table: Drive/Driving until Space, then Stop/Stopping on the next update.
    List<String> modes = new ArrayList<>();
    for (ArNetPacket p : PeerRecording.packets(s2c)) {
      if ("updateStrings".equals(then.get(p.getCommand()))) {
        ArNetPacket r = p.toReader();
        modes.add(r.bufToStr() + "/" + r.bufToStr());
      }
    }
    assertEquals(List.of("Stopped/Stop", "Driving/Drive", "Stopping/Stop", "Stopped/Stop"), modes);
    try (GuiRig rig = GuiRig.plain(b -> b);
        RawClient aria = new RawClient(rig.gui.getServer().getPort())) {
      ArServerBase s = rig.gui.getServer();
      List<ArNetPacket> now =
          PeerRecording.packets(PeerRecording.renumbered(c2s, s2c, s::findCommandFromName));
      int drive = s.findCommandFromName("ratioDrive");
      aria.readIntroduction();
      // The login and requests, then the ratioDrives at the rate recorded (about 600 a second:
      // 60 per 100 ms cycle), then the stop.
      int i = 0;
      ByteArrayOutputStream head = new ByteArrayOutputStream();
      while (now.get(i).getCommand() != drive) {
        head.writeBytes(now.get(i++).toWire());
      }
      aria.send(head.toByteArray());
      aria.readUntil(Protocol.SERVER_CONNECTED);
      while (now.get(i).getCommand() == drive) {
        ByteArrayOutputStream cycle = new ByteArrayOutputStream();
        int n = 0;
        for (; n < 60 && now.get(i).getCommand() == drive; n++) {
          cycle.writeBytes(now.get(i++).toWire());
        }
        long before = s.getStats().getRequests();
        aria.send(cycle.toByteArray());
        int sentNow = n;
        Eventually.until(
            "a cycle's requests read", () -> s.getStats().getRequests() >= before + sentNow);
        rig.run(100);
      }
      assertTrue(rig.robot.getVel() > 700, "driving as by hand: " + rig.robot.getVel());
      long before = s.getStats().getRequests();
      aria.send(now.get(i).toWire());
      Eventually.until("the stop read", () -> s.getStats().getRequests() > before);
      rig.run(100);
      assertEquals("Stop", ArServerModes.of(s).getMode(), "stopped at the next cycle");
      assertTrue(rig.runUntil(() -> Math.abs(rig.robot.getVel()) < 5, 5000), "and halted");
      assertEquals(0, s.getStats().getBusy(), "nothing refused as busy");
      assertTrue(s.getStats().getSuperseded() > 3000, "the flood was coalesced, not queued");
    }
  }

  @Test
  void ptzCameraClientExampleFindsTheCameraAndPansAndTiltsIt() throws Exception {
    byte[] c2s = PeerRecording.bytes("ptzCameraClientExample.c2s.bin");
    byte[] s2c = PeerRecording.bytes("ptzCameraClientExample.s2c.bin");
    Map<Integer, String> then = PeerRecording.listedCommands(PeerRecording.packets(s2c));
    // By hand: "1 cameras in list", "13 commands for camera 'Cam1' (VCC4)", then the pan range
    // (-9.8, 9.8) in its own units, and the position following its six stages.
    ArNetPacket listThen =
        PeerRecording.packets(s2c).stream()
            .filter(p -> "getCameraList".equals(then.get(p.getCommand())))
            .findFirst()
            .orElseThrow()
            .toReader();
    CameraInfo cam = CameraInfo.readList(listThen).get(0);
    assertEquals("Cam1", cam.name());
    assertEquals(13, cam.commands().size());
    GuiServerCameraTest.FakeVcc4 vcc4 = new GuiServerCameraTest.FakeVcc4();
    try (GuiRig rig = GuiRig.plain(b -> b.ptz(vcc4));
        RawClient aria = new RawClient(rig.gui.getServer().getPort())) {
      ArServerBase s = rig.gui.getServer();
      aria.readIntroduction();
      aria.send(PeerRecording.renumbered(c2s, s2c, s::findCommandFromName));
      int data = s.findCommandFromName("getCameraDataCam1");
      // The moves run on the robot's cycle: advance it while they wait.
      Eventually.until(
          "six moves",
          () -> {
            if (s.getPendingCycleCommands() > 0) {
              rig.sim.world().step();
            }
            return vcc4.history.size() >= 6;
          });
      readStepping(rig, aria, data);
      List<String> seen = new ArrayList<>();
      for (double[] pt : vcc4.history) {
        seen.add((int) pt[0] + "," + (int) pt[1]);
      }
      assertEquals(List.of("-98,0", "98,0", "0,0", "0,-30", "0,88", "0,0"), seen);
    }
  }

  @Test
  void theCameraRequestsAreServerDemosForItsVcc4AndTheCameraListIsAdded() throws Exception {
    // serverDemo, forwarding ACTS's video, sets up its VC-C4 as camera "Cam1" (without a camera
    // list: ptzCameraClientExample answered it "Error, server does not have any camera control
    // requests"). JAria lists the same requests, in the same words, and the list.
    List<ArNetPacket> s2c = PeerRecording.packets(PeerRecording.bytes("serverDemo-camera.s2c.bin"));
    Map<String, DataInfo> demo = listed(s2c);
    assertFalse(demo.containsKey("getCameraList"));
    GuiServerCameraTest.FakeVcc4 vcc4 = new GuiServerCameraTest.FakeVcc4();
    try (GuiRig rig = GuiRig.plain(b -> b.ptz(vcc4))) {
      Map<String, DataInfo> ours = new java.util.HashMap<>();
      for (DataInfo d : rig.gui.getServer().dataList()) {
        ours.put(d.name(), d);
      }
      int compared = 0;
      for (DataInfo d : demo.values()) {
        boolean camera = d.commandGroup().startsWith("Camera");
        if (!camera || d.name().equals("setCameraPctCam1")) {
          continue; // setCameraPct needs a field of view (PROTOCOL.md)
        }
        DataInfo o = ours.get(d.name());
        assertTrue(o != null, "JAria lists " + d.name());
        assertEquals(d.description(), o.description(), d.name());
        assertEquals(d.argumentDescription(), o.argumentDescription(), d.name());
        assertEquals(d.returnDescription(), o.returnDescription(), d.name());
        assertEquals(d.commandGroup(), o.commandGroup(), d.name());
        assertEquals(d.dataFlags(), o.dataFlags(), d.name());
        compared++;
      }
      assertEquals(13, compared);
      assertTrue(ours.containsKey("getCameraList"));
    }
  }

  /** The data a recorded server listed, by name, with descriptions, group and flags. */
  private static Map<String, DataInfo> listed(List<ArNetPacket> s2c) {
    Map<Integer, String[]> byId = new java.util.HashMap<>();
    for (ArNetPacket p : s2c) {
      int cmd = p.getCommand();
      if (cmd != Protocol.SERVER_LIST
          && cmd != Protocol.SERVER_LIST_ARGRET
          && cmd != Protocol.SERVER_LIST_GROUP_AND_FLAGS) {
        continue;
      }
      ArNetPacket r = p.toReader();
      int n = r.bufToUByte2();
      int slot = cmd == Protocol.SERVER_LIST ? 0 : cmd == Protocol.SERVER_LIST_ARGRET ? 2 : 4;
      for (int k = 0; k < n; k++) {
        String[] f = byId.computeIfAbsent(r.bufToUByte2(), x -> new String[6]);
        f[slot] = r.bufToStr();
        f[slot + 1] = r.bufToStr();
      }
    }
    Map<String, DataInfo> out = new java.util.HashMap<>();
    for (Map.Entry<Integer, String[]> e : byId.entrySet()) {
      String[] f = e.getValue();
      out.put(f[0], new DataInfo(e.getKey(), f[0], f[1], f[2], f[3], f[4], f[5]));
    }
    return out;
  }
}
