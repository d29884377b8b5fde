package org.jaria.tools.desktop;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.ServiceLoader;
import java.util.concurrent.Callable;
import org.jaria.desktop.spi.DesktopApps;
import org.jaria.sim.SimWorld;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Unmatched;

/**
 * Finds the desktop apps on the class path, or stands in for them: {@code jaria --help} lists every
 * app either way, and an app asked for without them says how to get them instead of failing with a
 * missing JavaFX class.
 */
public final class Desktop {

  /** A desktop app's command: its name and the first line of its description. */
  public record App(String name, String summary) {}

  /**
   * The desktop apps' commands, in the order {@code jaria --help} lists them. The {@code ./jaria}
   * launcher's list of app commands ({@code app_commands=} in the script) names the same; a system
   * test (DesktopAppsProviderTest in system-tests) checks both against the real commands.
   */
  public static final List<App> APPS =
      List.of(
          new App(
              "mapper",
              "Map editor: open, draw and save ArMap .map files (walls, points, goals, home, docks,"
                  + " forbidden lines and areas)."),
          new App(
              "eztrain",
              "EZ-Train: train ACTS color channels on a still image or live video, with the ACTS"
                  + " server running (port 5001) so robot programs see the channels as they are"
                  + " trained."),
          new App(
              "monitor",
              "The robot monitor (MobileEyes) for a guiServer (./jaria demo guiserver)."),
          new App(
              "simview",
              "The simulator with a window: map, robots, sonar, laser, camera field of view, true"
                  + " pose against odometry; run/pause, step and speed; place robots and move"
                  + " obstacles with the mouse. Robots listen on TCP 8101, 8102... unless"
                  + " --no-listen."),
          new App("screenshot", "Render a desktop app's window to a PNG file, without a display."));

  /** The benchmarks that need the apps (JavaFX or OpenCV): {@code jaria bench NAME}. */
  public static final List<App> BENCHMARKS =
      List.of(
          new App(
              "vision",
              "Blob tracking per frame at three sizes and 1/8/32 channels, against OpenCV."),
          new App(
              "mapper",
              "Map editor frame times (draw, and draw + pixels) while zooming and panning a"
                  + " 60,000-point map, headless software rendering."));

  private Desktop() {}

  /** The desktop apps, if they are on the class path. */
  public static Optional<DesktopApps> find() {
    return ServiceLoader.load(DesktopApps.class).findFirst();
  }

  /**
   * What to say when {@code what} needs the desktop apps and they are not on the class path: how to
   * get them (the launcher builds them on first use; a program of one's own adds the {@code apps}
   * module).
   */
  public static String missing(String what) {
    return what
        + " needs the part of JAria that uses JavaFX and OpenCV (the module apps: desktop apps,"
        + " windows, live cameras), which this command line was started without. ./jaria builds"
        + " it the first time a command needs it (a few minutes, and JavaFX and OpenCV are"
        + " downloaded once): run the same command through ./jaria, or put org.jaria:apps on your"
        + " program's class path.";
  }

  /**
   * The app commands for {@code jaria}: the real ones from {@code apps}, or one stand-in per app
   * that accepts any arguments and says, on its error stream, how to get the app.
   */
  public static List<CommandLine> appCommands(Optional<DesktopApps> apps) {
    return commands(apps.map(DesktopApps::commands), APPS, "jaria ");
  }

  /** The {@code jaria bench} subcommands that need the apps, real or stand-ins. */
  public static List<CommandLine> benchCommands(Optional<DesktopApps> apps) {
    return commands(apps.map(DesktopApps::benchmarks), BENCHMARKS, "jaria bench ");
  }

  private static List<CommandLine> commands(
      Optional<List<Object>> real, List<App> names, String prefix) {
    List<CommandLine> out = new ArrayList<>();
    if (real.isPresent()) {
      for (Object c : real.get()) {
        out.add(new CommandLine(c));
      }
      return out;
    }
    for (App a : names) {
      CommandLine cl = new CommandLine(new StandIn(prefix + a.name()));
      cl.getCommandSpec().name(a.name());
      cl.getCommandSpec()
          .usageMessage()
          .description(
              a.summary(), "(A desktop app: ./jaria builds it the first time it is used.)");
      out.add(cl);
    }
    return out;
  }

  /**
   * Shows {@code world} in the simulator view until its window is closed, or says on {@code err}
   * why it cannot ({@code who} names the command, e.g. {@code "jaria sim --gui"}).
   *
   * @return the exit status: 0, or 1 if no window was shown
   */
  public static int showUntilClosed(String who, SimWorld world, double speedup, PrintWriter err) {
    Optional<DesktopApps> apps = find();
    if (apps.isEmpty()) {
      err.println(who + ": " + missing("The simulator view"));
      err.flush();
      return 1;
    }
    return apps.get().showUntilClosed(world, speedup, err);
  }

  /**
   * Why a command's {@code --gui} cannot show a window here: the apps are missing, or there is no
   * display; empty if it can.
   */
  public static Optional<String> problem() {
    Optional<DesktopApps> apps = find();
    if (apps.isEmpty()) {
      return Optional.of(missing("The simulator view"));
    }
    return apps.get().problem();
  }

  /** Hides every window the apps show (nothing without the apps). */
  public static void closeWindows() {
    find().ifPresent(DesktopApps::closeWindows);
  }

  /** An app's stand-in: takes whatever it is given and says how to get the app. */
  @Command(mixinStandardHelpOptions = false)
  static final class StandIn implements Callable<Integer> {

    private final String command;

    @Spec CommandSpec spec;

    @Unmatched List<String> args = new ArrayList<>();

    StandIn(String command) {
      this.command = command;
    }

    @Override
    public Integer call() {
      PrintWriter err = spec.commandLine().getErr();
      err.println(command + ": " + missing("This command"));
      err.flush();
      return 1;
    }
  }
}
