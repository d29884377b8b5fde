package org.jaria.tools.mapper;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import javafx.stage.Stage;
import org.jaria.tools.fx.AppCommand;
import org.jaria.tools.fx.AppEnvironment;
import org.jaria.tools.fx.AppLauncher;
import org.jaria.tools.fx.DesktopApp;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code jaria mapper [FILE]}: the map editor (a Mapper3-Basic analogue). */
@Command(
    name = "mapper",
    mixinStandardHelpOptions = true,
    description = {
      "Map editor: open, draw and save ArMap .map files (walls, points, goals, home, docks,"
          + " forbidden lines and areas).",
      "Keys: S select, H pan, W wall, P point, G goal, Shift+G goal with heading, O home, K dock,"
          + " F forbidden line, A forbidden area, M measure; wheel zooms, right-drag pans."
    })
public final class MapperCommand implements Callable<Integer>, AppCommand {

  @Spec CommandSpec spec;

  @Parameters(index = "0", arity = "0..1", paramLabel = "FILE", description = "Map to open.")
  Path file;

  @Override
  public String appName() {
    return "mapper";
  }

  @Override
  public DesktopApp open(Stage stage, AppEnvironment env) {
    MapperWindow w = new MapperWindow(stage, env);
    w.show(file);
    return w;
  }

  @Override
  public Integer call() {
    return AppLauncher.runUntilClosed(this, spec.commandLine().getErr());
  }
}
