package org.jaria.apps.screenshot;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import javafx.scene.image.WritableImage;
import javafx.stage.Stage;
import org.jaria.apps.eztrain.EzTrainCommand;
import org.jaria.apps.fx.AppCommand;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.DesktopApp;
import org.jaria.apps.fx.FxImages;
import org.jaria.apps.fx.FxRuntime;
import org.jaria.apps.fx.HeadlessPrompts;
import org.jaria.apps.mapper.MapperCommand;
import org.jaria.apps.simview.SimViewCommand;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Unmatched;

/**
 * {@code jaria screenshot APP [args] -o FILE.png}: opens a desktop app without a display (on
 * Monocle's Headless platform with software rendering), waits until it shows its content, and
 * writes the window to a PNG file. APP is {@code mapper}, {@code eztrain} or {@code simview} (alias
 * {@code sim}); the arguments are the app's own.
 */
@Command(
    name = "screenshot",
    mixinStandardHelpOptions = true,
    customSynopsis = "jaria screenshot APP [APP-ARGS...] -o FILE.png [--size WxH] [--timeout S]",
    description = {
      "Render a desktop app's window to a PNG file, without a display.",
      "Examples:",
      "  jaria screenshot mapper columbia.map -o mapper.png",
      "  jaria screenshot eztrain --train 30,67,70,75 --view thresh -o eztrain.png",
      "  jaria screenshot simview --map office --demo --advance 3000 -o sim.png"
    })
public final class ScreenshotCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(
      names = {"-o", "--output"},
      required = true,
      paramLabel = "FILE.png",
      description = "Where to write the PNG.")
  Path output;

  @Option(
      names = "--size",
      paramLabel = "WxH",
      description = "Window size in pixels (default ${DEFAULT-VALUE}).",
      defaultValue = "1280x800")
  String size = "1280x800";

  @Option(
      names = "--timeout",
      paramLabel = "SECONDS",
      description = "Give up if the app is not ready after this long (default ${DEFAULT-VALUE}).",
      defaultValue = "120")
  int timeoutSeconds = 120;

  // APP and its own arguments (options included), in order: whatever is not ours.
  @Unmatched List<String> rest = new ArrayList<>();

  /** The command for app {@code name}, or null if there is no such app. */
  static AppCommand appCommand(String name) {
    return switch (name.toLowerCase(Locale.ROOT)) {
      case "mapper" -> new MapperCommand();
      case "eztrain" -> new EzTrainCommand();
      case "simview", "sim" -> new SimViewCommand();
      case "monitor" -> new org.jaria.apps.monitor.MonitorCommand();
      default -> null;
    };
  }

  @Override
  public Integer call() {
    PrintWriter err = spec.commandLine().getErr();
    PrintWriter out = spec.commandLine().getOut();
    int[] wh = parseSize(size);
    if (wh == null) {
      err.println("screenshot: --size must look like 1280x800, not '" + size + "'");
      return 2;
    }
    if (rest.isEmpty()) {
      err.println("screenshot: name the app to render: mapper, eztrain, simview or monitor");
      return 2;
    }
    String app = rest.get(0);
    List<String> appArgs = rest.subList(1, rest.size());
    AppCommand command = appCommand(app);
    if (command == null) {
      err.println("screenshot: no app '" + app + "'; choose mapper, eztrain, simview or monitor");
      return 2;
    }
    try {
      new CommandLine(command).parseArgs(appArgs.toArray(new String[0]));
    } catch (CommandLine.ParameterException e) {
      err.println("screenshot: " + app + ": " + e.getMessage());
      return 2;
    }
    FxRuntime.configureHeadless();
    FxRuntime.startup();
    try {
      WritableImage image = capture(command, wh[0], wh[1], timeoutSeconds);
      FxImages.writePng(image, output);
      out.println("wrote " + output + " (" + wh[0] + "x" + wh[1] + ")");
      return 0;
    } catch (Exception e) {
      err.println("screenshot: " + e.getMessage());
      return 1;
    } finally {
      // JavaFX keeps running: `jaria` exits the JVM after every command, and a test that renders
      // several screenshots in one JVM cannot restart the toolkit once it has stopped.
      out.flush();
      err.flush();
    }
  }

  /**
   * Opens the app in a {@code width × height} window, waits until it is ready, and returns the
   * window's picture. The toolkit must be running (headless for a picture without a display).
   *
   * @throws Exception if the app failed to start or reported an error (the message says which)
   */
  public static WritableImage capture(AppCommand command, int width, int height, int timeout)
      throws Exception {
    HeadlessPrompts prompts = new HeadlessPrompts();
    AppEnvironment env = AppEnvironment.headless(prompts);
    DesktopApp app =
        FxRuntime.call(
            () -> {
              Stage stage = new Stage();
              DesktopApp a = command.open(stage, env);
              stage.setX(0);
              stage.setY(0);
              stage.setWidth(width);
              stage.setHeight(height);
              return a;
            },
            timeout);
    try {
      try {
        app.ready().get(timeout, TimeUnit.SECONDS);
      } catch (ExecutionException e) {
        throw new IllegalStateException(firstError(prompts, e.getCause().getMessage()), e);
      } catch (TimeoutException e) {
        throw new IllegalStateException(
            command.appName() + " was not ready after " + timeout + " s", e);
      }
      if (!prompts.errors().isEmpty()) {
        throw new IllegalStateException(prompts.errors().get(0));
      }
      // Two pulses: layout after the last change, then a drawn frame.
      FxRuntime.run(() -> app.stage().getScene().getRoot().layout(), timeout);
      FxRuntime.run(() -> {}, timeout);
      return FxRuntime.call(() -> app.stage().getScene().snapshot(null), timeout);
    } finally {
      FxRuntime.run(
          () -> {
            app.stage().hide();
            app.close();
          },
          timeout);
    }
  }

  private static String firstError(HeadlessPrompts prompts, String fallback) {
    return prompts.errors().isEmpty() ? fallback : prompts.errors().get(0);
  }

  static int[] parseSize(String s) {
    String[] p = s.toLowerCase(Locale.ROOT).split("x", -1);
    if (p.length != 2) {
      return null;
    }
    try {
      int w = Integer.parseInt(p[0].trim());
      int h = Integer.parseInt(p[1].trim());
      return w >= 100 && h >= 100 && w <= 8000 && h <= 8000 ? new int[] {w, h} : null;
    } catch (NumberFormatException e) {
      return null;
    }
  }
}
