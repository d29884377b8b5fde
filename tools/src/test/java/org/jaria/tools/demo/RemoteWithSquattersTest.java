package org.jaria.tools.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.tools.bench.Attackers;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * {@code jaria demo goto --remote} reaches its goal on a simulator whose robot port ten silent
 * clients keep at, connecting again whenever they are dropped: they never hold the robot.
 */
@Tag("slow")
class RemoteWithSquattersTest {

  @Test
  void theDemoGetsTheRobotPastTenSquatters() throws Exception {
    try (SimWorld world = SimWorld.bundled("hall", SimOptions.builder().basePort(0).build())) {
      SimRobot robot = world.addRobot("p3dx-sh");
      world.listen();
      world.startRealTime(1);
      try (Attackers squatters = new Attackers(robot.getPort(), 10, false)) {
        squatters.awaitConnected();
        CommandLine cli = JariaCli.commandLine();
        StringWriter out = new StringWriter();
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(out, true));
        int status =
            cli.execute(
                "demo", "goto", "--remote", "127.0.0.1:" + robot.getPort(), "--pose", "500,0");
        assertEquals(0, status, out.toString());
        assertTrue(out.toString().contains("all goals reached"), out.toString());
        assertTrue(squatters.reconnects() > 0, "the squatters were at it the whole time");
      }
    }
  }
}
