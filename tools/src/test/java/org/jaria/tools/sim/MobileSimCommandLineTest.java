package org.jaria.tools.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.time.Duration;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** A MobileSim command line starts {@code ./jaria sim} with MobileSim's meanings. */
class MobileSimCommandLineTest {

  @Test
  void aTypicalMobileSimCommandLineBuildsTheWorldItDescribes() throws IOException {
    SimCommand cmd = new SimCommand();
    new CommandLine(cmd)
        .parseArgs(
            "-m",
            "office",
            "-r",
            "p3dx-sh:alice",
            "-r",
            "amigo",
            "-p",
            "0",
            "--start",
            "1000,2000,90",
            "--update-interval",
            "50",
            "--update-sim-time",
            "100",
            "--srisim-compat",
            "--no-srisim-laser-compat",
            "--nogui",
            "--lite-graphics",
            "--noninteractive",
            "--resolution",
            "20",
            "--no-error");
    try (SimWorld w = cmd.createWorld()) {
      List<SimRobot> robots = w.getRobots();
      assertEquals("alice", robots.get(0).getName(), "model:name");
      assertEquals("amigo", robots.get(1).getModel().getSubtype());
      assertEquals(new ArPose(1000, 2000, 90), robots.get(0).getTruePose(), "--start x,y,th");
      assertEquals(Duration.ofMillis(100), w.getTick(), "--update-sim-time is the tick");
    }
    assertEquals(2.0, cmd.pacing(), 1e-9, "100 ms simulated per 50 ms of wall time");
    StringWriter err = new StringWriter();
    cmd.noteDeprecatedOptions(new PrintWriter(err, true));
    String notes = err.toString();
    for (String o : new String[] {"--nogui", "--lite-graphics", "--noninteractive"}) {
      assertEquals(1, count(notes, o + " (a MobileSim option) has no meaning here"), notes);
    }
    assertTrue(notes.contains("--resolution is accepted"), notes);
  }

  @Test
  void noMapGivesAnEmptyWorldUnlessAMapIsGivenToo() throws IOException {
    SimCommand cmd = new SimCommand();
    new CommandLine(cmd).parseArgs("--nomap", "-p", "0");
    try (SimWorld w = cmd.createWorld()) {
      assertTrue(w.getMap().isEmpty());
    }
    SimCommand both = new SimCommand();
    new CommandLine(both).parseArgs("--nomap", "-map", "hall", "-p", "0");
    try (SimWorld w = both.createWorld()) {
      assertTrue(!w.getMap().isEmpty(), "as MobileSim: --nomap is ignored with -m");
    }
  }

  @Test
  void bindToAddressListensOnThatInterfaceOnly() throws IOException {
    SimCommand cmd = new SimCommand();
    new CommandLine(cmd).parseArgs("--bind-to-address", "127.0.0.1", "-p", "0");
    try (SimWorld w = cmd.createWorld()) {
      w.listen();
      int port = w.getRobot(0).getPort();
      try (Socket s = new Socket()) {
        s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 2000);
        assertTrue(s.isConnected());
      }
    }
    SimCommand bad = new SimCommand();
    new CommandLine(bad).parseArgs("--bind-to-address", "no.such.host.invalid", "-p", "0");
    CommandLine.ParameterException e =
        assertThrows(CommandLine.ParameterException.class, bad::createWorld);
    assertTrue(e.getMessage().contains("not an address of this machine"), e.getMessage());
  }

  @Test
  void robotFactoriesComeWithoutADefaultRobotAndBesideTheRobotsGiven() throws IOException {
    SimCommand only = new SimCommand();
    new CommandLine(only).parseArgs("-R", "p3dx-sh", "-p", "0");
    try (SimWorld w = only.createWorld()) {
      assertEquals(List.of(), w.getRobots(), "as MobileSim: no default robot beside a factory");
      assertEquals("p3dx-sh", w.getRobotFactories().get(0).getModel());
    }
    SimCommand both = new SimCommand();
    new CommandLine(both).parseArgs("-R", "amigo", "--robot-factory", "p3at-sh", "-r", "p3dx-sh");
    try (SimWorld w = both.createWorld()) {
      assertEquals(2, w.getRobotFactories().size());
      assertEquals("p3at-sh", w.getRobotFactories().get(1).getModel());
      assertEquals(1, w.getRobots().size());
    }
    SimCommand bad = new SimCommand();
    new CommandLine(bad).parseArgs("-R", "no-such-robot", "-p", "0");
    assertThrows(CommandLine.ParameterException.class, bad::createWorld);
  }

  /** A command that embeds {@code jaria sim}'s options, as {@code jaria sim --gui} does. */
  @CommandLine.Command(name = "wrapper")
  static final class Wrapper {
    @CommandLine.Mixin SimCommand sim = new SimCommand();
  }

  @Test
  void theMobileSimOptionsWorkWhenTheSimCommandIsAMixinToo() throws IOException {
    Wrapper w = new Wrapper();
    new CommandLine(w).parseArgs("-r", "amigo:bob", "-p", "0", "--nogui");
    StringWriter err = new StringWriter();
    w.sim.noteDeprecatedOptions(new PrintWriter(err, true));
    assertTrue(err.toString().contains("--nogui (a MobileSim option)"), err.toString());
    try (SimWorld world = w.sim.createWorld()) {
      assertEquals("bob", world.getRobot(0).getName());
    }
  }

  private static int count(String s, String what) {
    int n = 0;
    for (int i = s.indexOf(what); i >= 0; i = s.indexOf(what, i + 1)) {
      n++;
    }
    return n;
  }
}
