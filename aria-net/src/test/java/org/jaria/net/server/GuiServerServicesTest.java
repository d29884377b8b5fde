package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicReference;
import org.jaria.config.ArConfig;
import org.jaria.config.ArConfigArg;
import org.jaria.geom.ArPose;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.Futures;
import org.jaria.net.client.ArClientException;
import org.jaria.net.client.ArNetPacketArgs;
import org.jaria.net.data.CommandInfo;
import org.jaria.net.data.ConfigLayout;
import org.jaria.net.data.ConfigParam;
import org.jaria.net.data.ConfigSection;
import org.jaria.net.data.InfoStrings;
import org.jaria.net.data.MapData;
import org.jaria.net.data.PhysicalInfo;
import org.jaria.net.data.RangeReadings;
import org.jaria.net.data.RobotUpdate;
import org.jaria.net.data.SensorReadings;
import org.jaria.net.data.VideoFrame;
import org.jaria.net.protocol.NetError;
import org.jaria.net.provider.ArConfigRegistry;
import org.jaria.net.provider.VideoSource;
import org.junit.jupiter.api.Test;

/**
 * Every service of the guiServer as a monitor uses it, on a simulated robot in lockstep: state,
 * sensors, map, information strings, commands, configuration, video.
 */
class GuiServerServicesTest {

  /** The last update of {@code name}, decoded with {@code reader}. */
  private static <T> AtomicReference<T> watch(
      GuiRig rig, String name, java.util.function.Function<ArNetPacket, T> reader)
      throws Exception {
    AtomicReference<T> last = new AtomicReference<>();
    rig.client.addHandler(name, p -> last.set(reader.apply(p)));
    Futures.get(rig.client.request(name, 20));
    return last;
  }

  @Test
  void robotStateAndPhysicalInfo() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      AtomicReference<RobotUpdate> u = watch(rig, "update", RobotUpdate::read);
      rig.run(1000);
      ArPose at = rig.robot.getPose();
      // ArNetworking's update carries whole mm and degrees.
      Eventually.until(
          "an update of this pose",
          () ->
              u.get() != null && u.get().x() == (int) at.getX() && u.get().y() == (int) at.getY());
      RobotUpdate r = u.get();
      assertEquals("Stop", r.mode());
      assertEquals("Stopped", r.status());
      assertEquals((double) Math.round(at.getTh()), r.th(), 1);
      assertEquals(rig.robot.getBatteryVoltage(), r.batteryVoltage(), 0.05);
      assertFalse(r.eStop());
      PhysicalInfo p = PhysicalInfo.read(rig.call("physicalInfo"));
      assertEquals(rig.robot.getRobotType(), p.type());
      assertEquals(rig.robot.getRobotSubType(), p.subType());
      assertEquals((double) Math.round(rig.robot.getRobotWidth()), p.width(), 1e-9);
    }
  }

  @Test
  void rangeReadingsCurrentAndCumulative() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      AtomicReference<SensorReadings> s = new AtomicReference<>();
      rig.client.addHandler("getSensorCurrent", p -> s.set(SensorReadings.read(p)));
      Futures.get(rig.client.request("getSensorCurrent", 20, ArNetPacketArgs.of("sonar")));
      ArNetPacket sensors = rig.call("getSensorList");
      assertEquals(1, sensors.bufToByte2());
      assertEquals("sonar", sensors.bufToStr());
      rig.run(1500);
      Eventually.until(
          "readings after the run",
          () ->
              s.get() != null
                  && s.get().find("sonar") != null
                  && s.get().find("sonar").current().size() > 4);
      RangeReadings sonar = s.get().find("sonar");
      assertNotNull(sonar);
      assertTrue(sonar.current().size() > 4, "the robot in the corridor sees walls");
      ArPose at = rig.robot.getPose();
      for (ArPose p : sonar.current().toPoses()) {
        assertTrue(at.findDistanceTo(p) <= 5001, "global mm, in range: " + p);
      }
      RangeReadings cumulative = RangeReadings.read(rig.call("getSensorCumulative", "sonar"));
      assertTrue(cumulative.current().size() >= sonar.current().size());
      // ArNetworking's answer for a sensor the robot does not have: -1 readings.
      assertNull(RangeReadings.read(rig.call("getSensorCumulative", "laser")));
    }
  }

  @Test
  void theMapAndANewMap() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      MapData m = MapData.read(rig.call("getMap"), "office.map", 1);
      java.io.StringWriter w = new java.io.StringWriter();
      GuiRig.OFFICE.write(w);
      assertEquals(
          w.toString().replaceAll("\n+", "\n"), m.text(), "the map's lines (blank ones left out)");
      assertEquals(GuiRig.OFFICE.getGoals().size(), m.toArMap().getGoals().size());
      ArNetPacket name = rig.call("getMapName");
      assertEquals("office.map", name.bufToStr());
      java.util.concurrent.atomic.AtomicInteger updated =
          new java.util.concurrent.atomic.AtomicInteger();
      rig.client.addHandler("mapUpdated", p -> updated.incrementAndGet());
      Futures.get(rig.client.request("mapUpdated", -1));
      // ArNetworking does not acknowledge a request: a reply to a later packet shows it arrived.
      rig.call("getMapName");
      rig.gui.getMapHandler().setMap(org.jaria.map.ArMap.loadBundled("hall"), "hall.map");
      Eventually.until("mapUpdated", () -> updated.get() == 1);
      assertEquals("hall.map", rig.call("getMapName").bufToStr());
      MapData hall = MapData.read(rig.call("getMap"), "hall.map", 2);
      assertEquals(
          org.jaria.map.ArMap.loadBundled("hall").getGoals().size(),
          hall.toArMap().getGoals().size());
    }
  }

  @Test
  void informationStrings() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      rig.gui.getInfoGroup().addStringInt("Answer", 4, () -> 42);
      rig.gui.getInfoGroup().addStringString("Long", 3, () -> "abcdef");
      // ArNetworking's getStringsInfo: uByte2 count; per string its name and uByte2 max length.
      ArNetPacket info = rig.call("getStringsInfo");
      assertEquals(4, info.bufToUByte2());
      assertEquals("Robot cycle (ms)", info.bufToStr());
      assertEquals(8, info.bufToUByte2());
      assertEquals("Network clients", info.bufToStr());
      assertEquals(4, info.bufToUByte2());
      assertEquals("Answer", info.bufToStr());
      assertEquals(4, info.bufToUByte2());
      assertEquals("Long", info.bufToStr());
      assertEquals(3, info.bufToUByte2());
      assertFalse(info.hasMore());
      List<String> labels = InfoStrings.readLabels(rig.call("getStringsInfo"));
      // getStrings: the values only, one string each, in the same order.
      AtomicReference<InfoStrings> s = watch(rig, "getStrings", p -> InfoStrings.read(p, labels));
      Eventually.until("the table", () -> s.get() != null && s.get().get("Answer") != null);
      assertEquals("42", s.get().get("Answer"));
      assertEquals("abc", s.get().get("Long"), "cut to its maximum length");
      assertEquals("1", s.get().get("Network clients"));
    }
  }

  @Test
  void customCommands() throws Exception {
    List<String> said = new CopyOnWriteArrayList<>();
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      rig.gui.getCommands().addStringCommand("say", "logs a line", said::add);
      rig.gui
          .getCommands()
          .addCommand(
              "sum",
              "adds numbers",
              "numbers",
              Where.WORKER,
              args -> "" + args.stream().mapToLong(Long::parseLong).sum());
      // Commands added after a client logged in are listed to the next login.
      rig.client.disconnect();
      rig.client.connect("127.0.0.1", rig.gui.getServer().getPort(), "", "");
      ArNetPacket list = rig.call("listCommands");
      // ArNetworking's layout: byte2 count, then name and description per command.
      assertEquals(2, list.bufToByte2());
      assertEquals("enableMotors", list.bufToStr());
      assertEquals("switches the motors on", list.bufToStr());
      assertEquals("disableMotors", list.bufToStr());
      assertEquals("switches the motors off", list.bufToStr());
      assertFalse(list.hasMore());
      List<CommandInfo> withArgs = CommandInfo.readList(rig.call("listStringCommands"), true);
      assertEquals(
          List.of(
              new CommandInfo("say", "logs a line", CommandInfo.STRING_ARGUMENT),
              new CommandInfo("sum", "adds numbers", CommandInfo.STRING_ARGUMENT)),
          withArgs);
      assertFalse(rig.call("say", "hello", "3").hasMore(), "a command returns nothing");
      assertEquals(List.of("hello 3"), said);
      assertEquals("6", rig.call("sum", "1", "2", "3").bufToStr());
      rig.call("enableMotors");
      rig.run(300);
      assertTrue(rig.robot.areMotorsEnabled());
      rig.call("disableMotors");
      rig.run(300);
      assertFalse(rig.robot.areMotorsEnabled());
      ArClientException e = assertThrows(ArClientException.class, () -> rig.call("sum", "x"));
      assertEquals(NetError.FAILED, e.getCode());
    }
  }

  @Test
  void configurationGetAndSet() throws Exception {
    ArConfig config = new ArConfig();
    ArConfigArg speed = ArConfigArg.ofDouble("MaxSpeed", 500, "mm/s", 0, 2000);
    config.addParam(speed, "Teleop");
    config.addParam(ArConfigArg.ofString("Name", "r1", "the robot's name"), "Teleop");
    try (GuiRig rig = GuiRig.plain(b -> b.config(new ArConfigRegistry(config)))) {
      List<ConfigSection> sections = ConfigLayout.readAll(rig.call("getConfigBySections"));
      // ARIA's Files section (the map) in front of the program's own.
      assertEquals(List.of("Files", "Teleop"), sections.stream().map(ConfigSection::name).toList());
      ConfigParam p = sections.get(1).params().get(0);
      // ArNetworking's first layout carries no default value.
      assertEquals(new ConfigParam("MaxSpeed", "DOUBLE", "500.0", "", "0.0", "2000.0", "mm/s"), p);
      ArNetPacket ok = rig.call("setConfig", "Section", "Teleop", "MaxSpeed", "750");
      assertEquals("", ok.bufToStr(), "empty: all set");
      assertEquals(750, speed.getDouble());
      ArNetPacket refused =
          rig.call(
              "setConfig",
              "Section",
              "Teleop",
              "MaxSpeed",
              "5000",
              "Name",
              "r2",
              "Section",
              "Nope",
              "X",
              "1");
      String first = refused.bufToStr();
      assertTrue(first.contains("MaxSpeed"), "only the first refusal is told: " + first);
      assertFalse(refused.hasMore());
      assertEquals("r2", config.findParam("Name").orElseThrow().getString(), "the good one is set");
      assertEquals(750, speed.getDouble(), "the bad one is not");
    }
  }

  @Test
  void videoFrames() throws Exception {
    AtomicReference<VideoFrame> current = new AtomicReference<>();
    VideoSource camera =
        new VideoSource() {
          @Override
          public String getName() {
            return "Cam1";
          }

          @Override
          public VideoFrame getLatestFrame() {
            return current.get();
          }
        };
    try (GuiRig rig = GuiRig.plain(b -> b.video(camera))) {
      assertEquals("Cam1", rig.call("getVideoInfo").bufToStr());
      AtomicReference<VideoFrame> got = watch(rig, "getVideo", VideoFrame::read);
      // An ArNetworking packet holds at most 32000 bytes: a small RGB frame fits.
      byte[] rgb = new byte[80 * 60 * 3];
      for (int seq = 1; seq <= 3; seq++) {
        rgb[0] = (byte) seq;
        VideoFrame f = new VideoFrame(seq, VideoFrame.Format.RGB, 80, 60, rgb);
        current.set(f);
        Eventually.until("frame " + seq, () -> f.equals(got.get()));
      }
    }
  }
}
