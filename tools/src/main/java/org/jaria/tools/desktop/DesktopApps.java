package org.jaria.tools.desktop;

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
 * implementation. Without them, {@link Desktop} answers instead and says how to get them.
 */
public interface DesktopApps {

  /**
   * The apps' commands (picocli command objects), named and ordered as {@link Desktop#APPS} lists
   * them.
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
