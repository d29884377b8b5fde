package org.jaria.tools.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.ArRobotPacketReceiver;
import org.jaria.protocol.CommandCodec;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** {@code jaria sim}'s pacing options, the deprecated --lockstep and a run bounded by --seconds. */
class SimCommandPacingTest {

  private final StringWriter out = new StringWriter();
  private final StringWriter err = new StringWriter();

  private int run(String... args) {
    return new CommandLine(new SimCommand())
        .setOut(new PrintWriter(out, true))
        .setErr(new PrintWriter(err, true))
        .execute(args);
  }

  @Test
  void unthrottledRunsAsFastAsPossibleAndLockstepIsItsDeprecatedName() {
    SimCommand unthrottled = new SimCommand();
    new CommandLine(unthrottled).parseArgs("--unthrottled");
    assertEquals(0, unthrottled.pacing(), 1e-9);
    SimCommand old = new SimCommand();
    new CommandLine(old).parseArgs("--lockstep");
    assertEquals(0, old.pacing(), 1e-9);
    SimCommand paced = new SimCommand();
    new CommandLine(paced).parseArgs("--speedup", "2");
    assertEquals(2, paced.pacing(), 1e-9);
    assertEquals(1, new SimCommand().pacing(), 1e-9);

    StringWriter usage = new StringWriter();
    new CommandLine(new SimCommand()).usage(new PrintWriter(usage));
    assertTrue(usage.toString().contains("--unthrottled"), usage.toString());
    assertTrue(usage.toString().contains("--seconds"), usage.toString());
    assertFalse(usage.toString().contains("--lockstep"), "the old name is hidden");
  }

  @Test
  void aBoundedRunStopsByItselfAfterItsSimulatedSeconds() {
    assertEquals(0, run("--port", "0", "--unthrottled", "--seconds", "3"));
    String text = out.toString();
    assertTrue(text.contains("listening on TCP port"), text);
    assertTrue(text.contains("unthrottled"), text);
    assertTrue(text.contains("stops after 3.0 s of simulated time"), text);
    assertTrue(text.contains("simulator stopped"), text);
    assertEquals("", err.toString(), "no note without --lockstep");
  }

  @Test
  void theOldNameStillWorksAndSaysSo() {
    assertEquals(0, run("--port", "0", "--lockstep", "--seconds", "1"));
    assertTrue(err.toString().contains("--lockstep is deprecated"), err.toString());
    assertTrue(err.toString().contains("--unthrottled"), err.toString());
    assertTrue(out.toString().contains("simulator stopped"), out.toString());
  }

  @Test
  void zeroSecondsIsNoLimitAsInTheDemos() {
    SimCommand sim = new SimCommand();
    new picocli.CommandLine(sim).parseArgs("--seconds", "0");
    sim.buildOptions();
    assertEquals(null, sim.seconds, "no time limit");
  }

  @Test
  void badPacingOptionsSayWhatIsWrong() {
    assertEquals(2, run("--port", "0", "--seconds", "-1"));
    assertTrue(err.toString().contains("0 for no limit"), err.toString());
    err.getBuffer().setLength(0);
    assertTrue(run("--port", "0", "--unthrottled", "--speedup", "3") != 0);
    assertTrue(err.toString().contains("either --speedup or --unthrottled"), err.toString());
  }

  private static void send(ArDeviceConnection c, ArRobotPacket p) throws IOException {
    c.write(p.getBuf(), 0, p.getLength());
  }

  @Test
  void srisimLaserCommandsReachADefaultP3dx() throws IOException {
    SimCommand cmd = new SimCommand();
    new CommandLine(cmd).parseArgs("--port", "0");
    try (SimWorld w = cmd.createWorld()) {
      ArDeviceConnection c = w.getRobot(0).connectInMemory();
      List<ArRobotPacket> got = new ArrayList<>();
      ArRobotPacketReceiver rx = new ArRobotPacketReceiver(new DropCounters("test"));
      ArRobotPacket p = new ArRobotPacket();
      for (int sync = 0; sync < 3; sync++) {
        send(c, CommandCodec.com(p, sync));
      }
      send(c, CommandCodec.comInt(p, ArCommands.OPEN.getNumber(), 1));
      send(
          c,
          CommandCodec.comInt(
              p, ArCommands.GRIPPERVAL.getNumber(), -30)); // read as the old laser start angle
      send(
          c,
          CommandCodec.comInt(
              p, ArCommands.GRIPREQUEST.getNumber(), 30)); // read as the end angle, not a request
      send(c, CommandCodec.comInt(p, ArCommands.GYROCALCW.getNumber(), 100)); // 1 degree
      send(c, CommandCodec.comInt(p, ArCommands.ADSEL.getNumber(), 1)); // read as "laser on"
      w.advanceMillis(200);
      byte[] buf = new byte[8192];
      int n;
      while ((n = c.read(buf, 0, buf.length, 0)) > 0) {
        rx.feed(buf, 0, n, 0, q -> got.add(new ArRobotPacket().copyFrom(q)));
      }
      ArRobotPacket scan =
          got.stream().filter(q -> q.getID() == PacketIds.SIM_LASER).findFirst().orElseThrow();
      scan.resetRead();
      scan.skip(6);
      assertEquals(61, scan.bufToUByte2(), "-30..30 every degree: the option reached the robot");
      assertTrue(got.stream().noneMatch(q -> q.getID() == PacketIds.GRIPPER));
    }
    SimCommand off = new SimCommand();
    new CommandLine(off).parseArgs("--port", "0", "--no-srisim-laser-compat", "--srisim-compat");
    assertTrue(off.robotOptions("p3dx-sh").laser(), "still a laser");
    assertFalse(off.robotOptions("p3dx-sh").legacyLaserCommands(), "35-38 as on ARCOS");
    assertTrue(off.robotOptions("p3dx-sh").srisimCompat());
    SimCommand none = new SimCommand();
    new CommandLine(none).parseArgs("--port", "0", "--no-laser");
    try (SimWorld w = none.createWorld()) {
      assertNull(w.getRobot(0).getLaserScan(), "no laser, no scan");
      assertFalse(none.robotOptions("p3dx-sh").laser());
    }
  }
}
