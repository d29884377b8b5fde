package org.jaria.apps.mapper;

import java.util.concurrent.Callable;
import javafx.stage.Stage;
import org.jaria.apps.fx.AppCommand;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.AppLauncher;
import org.jaria.apps.fx.DesktopApp;
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

  @Parameters(
      index = "0",
      arity = "0..1",
      paramLabel = "MAP",
      description =
          "Map to open: a .map file, or a bundled map (columbia, office, hall; Save then asks"
              + " where to write it).")
  String map;

  @Override
  public String appName() {
    return "mapper";
  }

  @Override
  public DesktopApp open(Stage stage, AppEnvironment env) {
    MapSource source = map == null ? null : MapSource.resolve(map);
    MapperWindow w = new MapperWindow(stage, env);
    w.showMap(source);
    return w;
  }

  @Override
  public Integer call() {
    if (map != null) {
      try {
        MapSource.resolve(map); // said before a window opens
      } catch (IllegalArgumentException e) {
        spec.commandLine().getErr().println("jaria mapper: " + e.getMessage());
        return 2;
      }
    }
    return AppLauncher.runUntilClosed(this, spec.commandLine().getErr());
  }
}
