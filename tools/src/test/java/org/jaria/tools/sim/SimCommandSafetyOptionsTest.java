package org.jaria.tools.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Path;
import java.util.Set;
import org.jaria.sim.SimServerOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** MobileSim's --cwd and --ignore-command, as the "Hostile clients" section of the guide uses. */
class SimCommandSafetyOptionsTest {

  private static SimServerOptions parse(String... args) {
    SimCommand cmd = new SimCommand();
    new CommandLine(cmd).parseArgs(args);
    return cmd.buildOptions().server();
  }

  @Test
  void cwdAndIgnoreCommandAsInTheGuide(@TempDir Path maps) {
    SimServerOptions o =
        parse("--cwd", maps.toString(), "--ignore-command", "239", "--ignore-command", "224");
    assertEquals(maps, o.mapFolder());
    assertEquals(Set.of(239, 224), o.ignoredCommands());
    assertEquals(SimServerOptions.DEFAULTS.handshakeTimeoutMillis(), o.handshakeTimeoutMillis());
  }

  @Test
  void theDefaultsAreSafe() {
    SimServerOptions o = parse();
    assertNull(o.mapFolder(), "maps from the working directory, for local clients only");
    assertEquals(Set.of(), o.ignoredCommands());
    assertEquals(false, o.remoteExit());
  }

  @Test
  void badValuesAreRefusedWithAMessage(@TempDir Path dir) {
    SimCommand cmd = new SimCommand();
    CommandLine cl = new CommandLine(cmd);
    cl.parseArgs("--cwd", dir.resolve("no-such-folder").toString());
    assertThrows(CommandLine.ParameterException.class, cmd::buildOptions);
    SimCommand cmd2 = new SimCommand();
    new CommandLine(cmd2).parseArgs("--ignore-command", "300");
    assertThrows(CommandLine.ParameterException.class, cmd2::buildOptions);
  }
}
