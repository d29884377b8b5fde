package org.jaria.apps;

import java.io.PrintWriter;
import java.util.List;
import java.util.Optional;
import javafx.application.Platform;
import javafx.stage.Window;
import org.jaria.apps.bench.VisionBenchCommand;
import org.jaria.apps.eztrain.EzTrainCommand;
import org.jaria.apps.fx.GuiCheck;
import org.jaria.apps.mapper.MapperBenchCommand;
import org.jaria.apps.mapper.MapperCommand;
import org.jaria.apps.monitor.MonitorCommand;
import org.jaria.apps.screenshot.ScreenshotCommand;
import org.jaria.apps.simview.SimViewCommand;
import org.jaria.desktop.spi.DesktopApps;
import org.jaria.sim.SimWorld;

/**
 * The desktop apps for the {@code jaria} command line, found by {@link java.util.ServiceLoader}
 * when this module is on the class path (see {@link DesktopApps}).
 */
public final class DesktopAppsProvider implements DesktopApps {

  /** Used by {@link java.util.ServiceLoader}. */
  public DesktopAppsProvider() {}

  @Override
  public List<Object> commands() {
    return List.of(
        new MapperCommand(),
        new EzTrainCommand(),
        new MonitorCommand(),
        new SimViewCommand(),
        new ScreenshotCommand());
  }

  @Override
  public List<Object> benchmarks() {
    return List.of(new VisionBenchCommand(), new MapperBenchCommand());
  }

  @Override
  public Optional<String> problem() {
    return GuiCheck.problem();
  }

  @Override
  public int showUntilClosed(SimWorld world, double speedup, PrintWriter err) {
    return SimViewCommand.showUntilClosed(world, speedup, err);
  }

  @Override
  public void closeWindows() {
    Platform.runLater(() -> List.copyOf(Window.getWindows()).forEach(Window::hide));
  }
}
