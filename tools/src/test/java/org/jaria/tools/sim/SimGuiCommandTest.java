package org.jaria.tools.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;
import org.jaria.sim.RobotFactory;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** {@code jaria sim --gui}: every option of the simulator command plus --gui. */
class SimGuiCommandTest {

  @Test
  void keepsTheSimulatorsOptionsAndAddsGui() {
    SimGuiCommand c = new SimGuiCommand();
    CommandLine cl = new CommandLine(c);
    cl.parseArgs("--gui", "--map", "hall", "--speedup", "2.5", "--robots", "2");
    assertTrue(c.gui);
    assertEquals(2.5, c.speedup());
    StringWriter usage = new StringWriter();
    cl.usage(new PrintWriter(usage));
    for (String o :
        new String[] {"--gui", "--map", "--robot", "--port", "--unthrottled", "--laser"}) {
      assertTrue(usage.toString().contains(o), o);
    }
  }

  @Test
  void unthrottledMeansAsFastAsPossibleAndLockstepIsItsOldName() {
    SimGuiCommand c = new SimGuiCommand();
    new CommandLine(c).parseArgs("--gui", "--unthrottled");
    assertEquals(0, c.speedup());
    SimGuiCommand old = new SimGuiCommand();
    new CommandLine(old).parseArgs("--gui", "--lockstep");
    assertEquals(0, old.speedup());
    SimGuiCommand d = new SimGuiCommand();
    new CommandLine(d).parseArgs();
    assertEquals(1, d.speedup());
  }

  @Test
  void withARobotFactoryItSaysWhereTheFactoryListensAsTheHeadlessCommandDoes() throws Exception {
    SimGuiCommand c = new SimGuiCommand();
    new CommandLine(c).parseArgs("--gui", "-R", "p3at-sh", "-r", "p3dx-sh:first", "-p", "0");
    StringWriter out = new StringWriter();
    try (SimWorld w = c.openAndAnnounce(new PrintWriter(out))) {
      RobotFactory f = w.getRobotFactories().get(0);
      assertTrue(f.getPort() > 0, "the factory's port is open");
      assertEquals(
          List.of(
              "robot factory for p3at-sh listening on TCP port "
                  + f.getPort()
                  + " (a new robot for each client)",
              "robot first (p3dx-sh) listening on TCP port " + w.getRobot(0).getPort()),
          out.toString().lines().toList());
    }
  }
}
