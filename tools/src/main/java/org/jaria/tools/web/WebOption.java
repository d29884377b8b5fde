package org.jaria.tools.web;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.web.control.Controls;
import org.jaria.web.server.WebOptions;
import org.jaria.web.source.FrameSource;
import picocli.CommandLine.Option;

/**
 * The options that add a web view to a command ({@code jaria sim}, {@code demo}, {@code demo
 * guiserver}): {@code --web [PORT]}, {@code --web-bind}, {@code --allow-control} and {@code
 * --record}.
 */
public final class WebOption {

  @Option(
      names = "--web",
      arity = "0..1",
      paramLabel = "PORT",
      fallbackValue = "" + WebOptions.DEFAULT_PORT,
      description =
          "Also show it in a web browser: serve the page (and Foxglove's WebSocket protocol) on"
              + " PORT (default "
              + WebOptions.DEFAULT_PORT
              + "; 0: any free port)")
  Integer port;

  @Option(
      names = "--web-bind",
      paramLabel = "ADDRESS",
      description =
          "Address the web view listens on (default 127.0.0.1: this computer only; any other"
              + " address gets a secret token in the printed URL)")
  String bind = "127.0.0.1";

  @Option(
      names = "--allow-control",
      description =
          "Web viewers may drive the robot (arrow keys), send goals (click) and pause, step or"
              + " speed up the simulation; without it the web view is read-only")
  boolean allowControl;

  @Option(
      names = "--record",
      paramLabel = "FILE.mcap",
      description = "Record what the web view publishes to an MCAP file (Foxglove opens it)")
  Path record;

  /** Whether a web view or a recording was asked for. */
  public boolean enabled() {
    return port != null || record != null;
  }

  /** The server options these ask for. */
  public WebOptions options(String name) {
    int p = port != null ? port : 0;
    String b = port != null ? bind : "127.0.0.1";
    return WebOptions.loopback(p).withBind(b).withControl(allowControl).withName(name);
  }

  /**
   * Starts the web view, or returns null if none was asked for.
   *
   * @param extras closed after the server
   */
  public WebView start(
      String name, FrameSource source, Controls controls, PrintWriter out, AutoCloseable... extras)
      throws IOException {
    if (!enabled()) {
      return null;
    }
    return WebView.start(options(name), source, controls, record, port != null, out, extras);
  }

  /** The map file or bundled map {@code name} (for its goals and forbidden areas), or null. */
  public static ArMap mapOrNull(String name) {
    if (name == null) {
      return null;
    }
    try {
      return ArMap.load(name);
    } catch (IOException | MapFormatException | RuntimeException e) {
      return null;
    }
  }
}
