package org.jaria.tools.web;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.jaria.tools.ProjectVersion;
import org.jaria.web.control.Controls;
import org.jaria.web.mcap.McapRecorder;
import org.jaria.web.server.WebOptions;
import org.jaria.web.server.WebServer;
import org.jaria.web.source.FrameSource;

/**
 * A running web view for a command: the server, its recording, and whatever else the command's
 * source needs closed afterwards (a driver's action), closed in reverse order.
 */
public final class WebView implements AutoCloseable {

  private final WebServer server;
  private final List<AutoCloseable> extras;

  private WebView(WebServer server, List<AutoCloseable> extras) {
    this.server = server;
    this.extras = extras;
  }

  /**
   * Starts the server (and the recording), and prints where to open it.
   *
   * @param record the MCAP file to record to, or null
   * @param show whether to print the page's address (false: recording only)
   * @param extras closed after the server, last first
   */
  public static WebView start(
      WebOptions options,
      FrameSource source,
      Controls controls,
      Path record,
      boolean show,
      PrintWriter out,
      AutoCloseable... extras)
      throws IOException {
    McapRecorder rec = null;
    if (record != null) {
      try {
        rec = McapRecorder.create(record, "JAria " + ProjectVersion.get());
      } catch (IOException e) {
        throw new IOException(
            "cannot write the recording "
                + record
                + " ("
                + e.getMessage()
                + "): give a file in a"
                + " folder you can write to",
            e);
      }
    }
    WebServer server;
    try {
      server = WebServer.start(options, source, controls);
    } catch (IOException e) {
      if (rec != null) {
        rec.close();
      }
      throw e;
    }
    if (rec != null) {
      server.addSink(rec);
    }
    if (show) {
      out.printf(Locale.ROOT, "Web view: open %s in a browser%n", server.url());
      out.printf(
          Locale.ROOT,
          "  (Foxglove or Lichtblick: open a connection to %s; %s)%n",
          server.websocketUrl(),
          options.allowControl()
              ? "viewers may drive and run the simulation"
              : "read-only: --allow-control lets viewers drive");
      if (options.token() != null) {
        out.println(
            "  The address carries a secret token: give it only to those who may watch"
                + (options.allowControl() ? " and drive." : "."));
      }
    }
    if (record != null) {
      out.printf(Locale.ROOT, "Recording every channel to %s (MCAP)%n", record);
    }
    out.flush();
    return new WebView(server, new ArrayList<>(List.of(extras)));
  }

  /** The server. */
  public WebServer server() {
    return server;
  }

  /** Stops the server, finishes the recording (the server closes it), closes the extras. */
  @Override
  public void close() {
    server.close();
    for (int i = extras.size() - 1; i >= 0; i--) {
      try {
        extras.get(i).close();
      } catch (Exception e) {
        // Closing a driver's action on a robot that is already gone: nothing left to undo.
      }
    }
  }
}
