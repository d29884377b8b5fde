package org.jaria.apps.simview;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** {@code jaria simview}'s options build the world they describe. */
class SimViewCommandTest {

  @Test
  void simviewBuildsTheWorldItsOptionsDescribe() throws Exception {
    SimViewCommand c = new SimViewCommand();
    new CommandLine(c).parseArgs("--map", "hall", "--robot", "p3at-sh", "--robots", "3", "--laser");
    try (var w = c.createWorld()) {
      assertEquals(3, w.getRobots().size());
      assertEquals("p3at-sh", w.getRobot(2).getModel().getSubtype());
    }
  }
}
