package org.jaria.apps.monitor;

import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.function.BiFunction;
import javafx.application.Platform;
import javafx.scene.control.Button;
import javafx.scene.control.Label;
import javafx.scene.control.Tooltip;
import javafx.scene.layout.HBox;
import org.jaria.apps.fx.Prompts;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;

/**
 * The monitor's scan buttons (MobileEyes' "start scan"): on a guiServer that offers ArNetworking's
 * mapping services, "Scan…" asks for a file name and sends {@code mappingStart}, "End scan" sends
 * {@code mappingEnd}. The growing map itself comes as the server's drawing, which the monitor draws
 * like any other. The replies' meanings are plain functions ({@link #startReply}, {@link
 * #endReply}).
 */
final class ScanControls {

  private final Prompts prompts;
  private final BiFunction<String, Object[], CompletableFuture<ArNetPacket>> request;
  private final Button start = new Button("Scan…");
  private final Button end = new Button("End scan");
  private final Label status = new Label();
  private final HBox node = new HBox(6, start, end, status);

  /**
   * Buttons sending their requests with {@code request} (name and arguments; the reply's future).
   */
  ScanControls(
      Prompts prompts, BiFunction<String, Object[], CompletableFuture<ArNetPacket>> request) {
    this.prompts = prompts;
    this.request = request;
    start.setId("scan-start");
    end.setId("scan-end");
    status.setId("scan-status");
    start.setTooltip(
        new Tooltip("Start a laser scan log on the server; drive; then End scan builds the map"));
    start.setOnAction(e -> askAndStart());
    end.setOnAction(e -> end());
    setAvailable(false);
  }

  /** The buttons and their status, for a tool bar. */
  HBox node() {
    return node;
  }

  /** Enables the buttons if the server offers the mapping services. */
  void setAvailable(boolean offered) {
    start.setDisable(!offered);
    end.setDisable(!offered);
    start.setTooltip(
        new Tooltip(
            offered
                ? "Start a laser scan log on the server; drive; then End scan builds the map"
                : "This server offers no mapping (jaria demo guiserver --mapping does)"));
  }

  /** The status line's text (for tests). */
  String status() {
    return status.getText();
  }

  private void askAndStart() {
    Optional<String> name =
        prompts.askText("Start a scan", "File name of the scan (in the server's map folder)", "");
    name.filter(n -> !n.isBlank()).ifPresent(this::start);
  }

  /** Sends mappingStart with {@code name}. */
  void start(String name) {
    send("mappingStart", new Object[] {name}, ScanControls::startReply, "Cannot start the scan");
  }

  /** Sends mappingEnd. */
  void end() {
    send("mappingEnd", new Object[0], ScanControls::endReply, "Cannot end the scan");
  }

  private void send(
      String what,
      Object[] args,
      java.util.function.Function<ArNetPacket, Reply> meaning,
      String errorTitle) {
    request
        .apply(what, args)
        .whenComplete(
            (p, e) ->
                Platform.runLater(
                    () -> {
                      Reply r = e != null ? new Reply(false, e.getMessage()) : meaning.apply(p);
                      status.setText(r.text());
                      if (!r.ok()) {
                        prompts.error(errorTitle, r.text());
                      }
                    }));
  }

  /** What a reply means: whether all went well, and a sentence. */
  record Reply(boolean ok, String text) {}

  /** The meaning of mappingStart's reply (ArNetworking's byte, then JAria's reason after a 2). */
  static Reply startReply(ArNetPacket p) {
    try {
      int code = p.bufToByte();
      return switch (code) {
        case 0 -> new Reply(true, "Scanning: drive the robot, then End scan");
        case 1 -> new Reply(false, "A scan is running already: end it first");
        default ->
            new Reply(
                false,
                "The server could not start the scan"
                    + (p.hasMore() ? ": " + p.bufToStr() : " (its log says why)"));
      };
    } catch (ArNetPacketException e) {
      return new Reply(false, "The server's answer could not be read: " + e.getMessage());
    }
  }

  /**
   * The meaning of mappingEnd's reply: ArNetworking answers "no scan" with one byte (1) and an
   * ended scan with two (0, or 2 if the log could not be kept).
   */
  static Reply endReply(ArNetPacket p) {
    try {
      if (p.getDataLength() == 1) {
        return p.bufToByte() == 1
            ? new Reply(false, "No scan is running")
            : new Reply(false, "The server's answer could not be read");
      }
      int code = p.bufToUByte2();
      return code == 0
          ? new Reply(true, "Scan ended: the server builds its map in its map folder")
          : new Reply(false, "The server could not keep the scan's log (its log says why)");
    } catch (ArNetPacketException e) {
      return new Reply(false, "The server's answer could not be read: " + e.getMessage());
    }
  }
}
