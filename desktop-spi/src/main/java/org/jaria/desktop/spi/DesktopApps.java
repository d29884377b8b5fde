package org.jaria.desktop.spi;

import java.io.PrintWriter;
import java.util.List;
import java.util.Optional;
import org.jaria.sim.SimWorld;

/**
 * The desktop apps (map editor, EZ-Train, monitor, simulator view and {@code jaria screenshot}) as
 * the command line uses them. They are JavaFX programs in a module of their own ({@code apps}), so
 * that the command line starts, and builds the first time, without JavaFX or OpenCV; the {@code
 * ./jaria} launcher builds them the first time an app is asked for and then runs the command line
 * with them on the class path, where {@link java.util.ServiceLoader} finds this interface's one
 * implementation. Without them, the command line's stand-ins ({@code
 * org.jaria.tools.desktop.Desktop} in module {@code tools}) answer instead and say how to get them.
 *
 * <p>This interface is a module of its own ({@code desktop-spi}) so that neither side depends on
 * the other: the command line ({@code tools}) looks it up, the apps ({@code apps}) implement it,
 * and the two build side by side.
 */
public interface DesktopApps {

  /**
   * The apps' commands (picocli command objects), named and ordered as the command line's list of
   * apps ({@code Desktop.APPS} in {@code tools}) names them.
   */
  List<Object> commands();

  /** Benchmarks that need JavaFX, as {@code jaria bench} subcommands (picocli command objects). */
  List<Object> benchmarks();

  /** Why no window can be shown on this computer (no display, no graphics), or empty if one can. */
  Optional<String> problem();

  /**
   * Shows {@code world} in the simulator view until the user closes the window (or {@link
   * #closeWindows} is called), the world running at {@code speedup} times real time (0: as fast as
   * possible). Problems are reported on {@code err}.
   *
   * @return 0, or 1 if the window could not be shown
   */
  int showUntilClosed(SimWorld world, double speedup, PrintWriter err);

  /** Hides every window shown so far, from any thread (a demo whose time is up). */
  void closeWindows();
}
