package org.jaria.system;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.jaria.acts.camera.OpenCvCameras;
import org.jaria.acts.image.Cameras;
import org.jaria.apps.DesktopAppsProvider;
import org.jaria.apps.mapper.MapperCommand;
import org.jaria.desktop.spi.DesktopApps;
import org.jaria.tools.cli.JariaCli;
import org.jaria.tools.desktop.Desktop;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * With the apps module on the class path (beside the command line, as {@code ./jaria} runs the
 * commands that need it), {@code jaria} finds the real apps, benchmarks and camera driver; their
 * names and summaries are the ones the command line's stand-ins show without it, and the {@code
 * ./jaria} launcher's lists of commands that need this module name the same.
 */
class DesktopAppsProviderTest {

  private static List<String> names(List<Object> commands) {
    return commands.stream().map(c -> new CommandLine(c).getCommandName()).toList();
  }

  private static String summary(Object command) {
    return new CommandLine(command).getCommandSpec().usageMessage().description()[0];
  }

  @Test
  void theCommandLineFindsTheApps() {
    DesktopApps apps = Desktop.find().orElseThrow();
    assertInstanceOf(DesktopAppsProvider.class, apps);
    CommandLine jaria = JariaCli.commandLine();
    assertInstanceOf(MapperCommand.class, jaria.getSubcommands().get("mapper").getCommand());
    assertInstanceOf(OpenCvCameras.class, Cameras.driver().orElseThrow());
  }

  @Test
  void theStandInsNameAndDescribeTheRealCommands() {
    DesktopApps apps = new DesktopAppsProvider();
    assertEquals(Desktop.APPS.stream().map(Desktop.App::name).toList(), names(apps.commands()));
    for (int i = 0; i < Desktop.APPS.size(); i++) {
      assertEquals(Desktop.APPS.get(i).summary(), summary(apps.commands().get(i)));
    }
    assertEquals(
        Desktop.BENCHMARKS.stream().map(Desktop.App::name).toList(), names(apps.benchmarks()));
    for (int i = 0; i < Desktop.BENCHMARKS.size(); i++) {
      assertEquals(Desktop.BENCHMARKS.get(i).summary(), summary(apps.benchmarks().get(i)));
    }
  }

  @Test
  void theLauncherBuildsTheAppsForTheseCommands() throws Exception {
    String script = Files.readString(Path.of("..", "jaria"), StandardCharsets.UTF_8);
    assertEquals(
        Desktop.APPS.stream().map(Desktop.App::name).toList(), listed(script, "app_commands"));
    assertEquals(
        Desktop.BENCHMARKS.stream().map(Desktop.App::name).toList(),
        listed(script, "app_benchmarks"));
  }

  private static List<String> listed(String script, String variable) {
    Matcher m = Pattern.compile("(?m)^" + variable + "=\"([^\"]*)\"").matcher(script);
    assertTrue(m.find(), "the launcher sets " + variable);
    return Arrays.asList(m.group(1).split(" "));
  }
}
