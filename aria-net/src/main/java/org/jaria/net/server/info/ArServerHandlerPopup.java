package org.jaria.net.server.info;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.LongSupplier;
import org.jaria.net.ArNetPacket;
import org.jaria.net.data.PopupInfo;
import org.jaria.net.data.PopupLayout;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.Where;

/**
 * Popup windows on the clients (ArNetworking's {@code ArServerHandlerPopup}), in its layouts
 * ({@link PopupLayout}): {@link #createPopup} broadcasts {@code "popupCreate"} to the clients that
 * asked for it (request it with interval -1), a client's {@code "popupClicked"} closes the popup
 * for everybody with {@code "popupClose"}, {@code "popupList"} sends the open ones again, and a
 * popup with a timeout closes by itself. The callback hears which button closed a popup (-1: timed
 * out, -2: closed by the server).
 *
 * <pre>{@code
 * int id = popups.createPopup(
 *     PopupInfo.message("Battery", "The battery is low", PopupInfo.PopupType.WARNING),
 *     (popup, button) -> log.info("popup {} closed by {}", popup, button));
 * }</pre>
 */
public final class ArServerHandlerPopup {

  /** Hears how a popup closed. */
  @FunctionalInterface
  public interface Callback {
    /**
     * Popup {@code id} closed.
     *
     * @param button the button pressed, -1 if it timed out, -2 if the server closed it
     */
    void closed(int id, int button);
  }

  private static final String GROUP = "PopupGui";

  private final ArServerBase server;
  private final LongSupplier clockMs;

  @GuardedBy("this")
  private final PopupBook book = new PopupBook();

  @GuardedBy("this")
  private final Map<Integer, Callback> callbacks = new HashMap<>();

  /**
   * Registers the popup data with {@code server}; timeouts are checked on the server's robot cycle
   * against {@code clockMs} (milliseconds, any origin).
   */
  public ArServerHandlerPopup(ArServerBase server, LongSupplier clockMs) {
    this.server = Objects.requireNonNull(server, "server");
    this.clockMs = Objects.requireNonNull(clockMs, "clockMs");
    server.addData(
        "popupCreate",
        "Tells the gui to create a new popup",
        "none (you can't send this command to the server)",
        "byte4: id of this particular popup; string: ignoreIdentifier; string: title; string:"
            + " message; byte: popupType (0 = NoIcon, 1 = Information, 2 = Warning, 3 = Critical,"
            + " 4 = Question); string: button0Label; string: button1Label; string: button2Label;"
            + " byte: defaultButton; byte: escapeButton",
        GROUP,
        "RETURN_SINGLE",
        Where.WORKER,
        // Only broadcasts answer it: a request (interval -1) subscribes and gets nothing now.
        (client, request, reply) -> {});
    server.addData(
        "popupClose",
        "Closes a popup that was created",
        "none (you can't send this command to the server)",
        "byte4: id of the popup to close; string: string to display",
        GROUP,
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> {});
    server.addData(
        "popupClicked",
        "Returns the clicked data of a popup ",
        "byte4: id of the popup that was clicked; byte: buttonClicked",
        "no response",
        GROUP,
        "RETURN_NONE",
        Where.WORKER,
        (client, request, reply) -> clicked(request.bufToByte4(), request.bufToByte()));
    server.addData(
        "popupList",
        "Resends all the popupCreates to this client that asked for this",
        "none",
        "technically none, but it resends all the popupCreate events that are active",
        GROUP,
        "RETURN_NONE",
        Where.WORKER,
        (client, request, reply) -> {
          int cmd = server.findCommandFromName("popupCreate");
          for (PopupBook.Open o : openPopups()) {
            ArNetPacket p = new ArNetPacket(cmd);
            PopupLayout.writeCreate(p, o.id(), o.info());
            client.sendPacketTcp(p);
          }
          // As ArNetworking's server (seen on the wire from ARIA's popupExample): an empty
          // popupList packet ends the list, although popupList returns nothing.
          client.sendPacketTcp(new ArNetPacket(server.findCommandFromName("popupList")));
        });
    server.addCycleTask("popup timeouts", this::checkTimeouts);
  }

  /**
   * Opens a popup on every client listening for {@code popupCreate}.
   *
   * @param callback told how it closed (may be null)
   * @return the popup's number
   */
  public int createPopup(PopupInfo info, Callback callback) {
    Objects.requireNonNull(info, "info");
    int id;
    synchronized (this) {
      id = book.create(info, clockMs.getAsLong());
      if (callback != null) {
        callbacks.put(id, callback);
      }
    }
    ArNetPacket p = new ArNetPacket();
    PopupLayout.writeCreate(p, id, info);
    server.broadcastPacketTcp(p, "popupCreate");
    return id;
  }

  /** Closes popup {@code id} on every client, showing {@code message} (nothing if not open). */
  public void closePopup(int id, String message) {
    PopupBook.Done d;
    synchronized (this) {
      d = book.close(id, Objects.toString(message, ""));
    }
    finish(d);
  }

  /** The popups open now, oldest first. */
  public synchronized List<PopupInfo> getOpenPopups() {
    return book.open().stream().map(PopupBook.Open::info).toList();
  }

  private synchronized List<PopupBook.Open> openPopups() {
    return book.open();
  }

  private void clicked(int id, int button) {
    PopupBook.Done d;
    synchronized (this) {
      d = book.click(id, button);
    }
    finish(d);
  }

  private void checkTimeouts() {
    List<PopupBook.Done> done;
    synchronized (this) {
      done = book.expire(clockMs.getAsLong());
    }
    done.forEach(this::finish);
  }

  private void finish(PopupBook.Done d) {
    if (d == null) {
      return;
    }
    Callback cb;
    synchronized (this) {
      cb = callbacks.remove(d.id());
    }
    if (cb != null) {
      cb.closed(d.id(), d.button());
    }
    ArNetPacket p = new ArNetPacket();
    PopupLayout.writeClose(p, d.id(), d.message());
    server.broadcastPacketTcp(p, "popupClose");
  }
}
