package org.jaria.net.server.info;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.jaria.net.data.PopupInfo;

/**
 * The popups a server has open, as plain values (not thread-safe; {@link ArServerHandlerPopup}
 * guards it): numbering as ArNetworking numbers them (the next positive number not in use), closing
 * by a button, by the server, or by a timeout measured on the clock the caller gives.
 */
final class PopupBook {

  /** An open popup. */
  record Open(int id, PopupInfo info, long openedMs) {}

  /**
   * A popup that has closed.
   *
   * @param id its number
   * @param button the button pressed, -1 for a timeout, -2 when the server closed it
   * @param message what clients are told
   */
  record Done(int id, int button, String message) {}

  private final Map<Integer, Open> open = new LinkedHashMap<>();
  private int lastId;

  /** Opens a popup at time {@code nowMs} and returns its number. */
  int create(PopupInfo info, long nowMs) {
    do {
      lastId = lastId == Integer.MAX_VALUE ? 1 : lastId + 1;
    } while (open.containsKey(lastId));
    open.put(lastId, new Open(lastId, info, nowMs));
    return lastId;
  }

  /** Button {@code button} of popup {@code id} was pressed: null if it is not open. */
  Done click(int id, int button) {
    Open o = open.remove(id);
    return o == null ? null : new Done(id, button, o.info().pressedText(button));
  }

  /** The server closes popup {@code id} showing {@code message}: null if it is not open. */
  Done close(int id, String message) {
    return open.remove(id) == null ? null : new Done(id, -2, message);
  }

  /** Closes the popups whose timeout has passed at {@code nowMs}. */
  List<Done> expire(long nowMs) {
    List<Done> done = new ArrayList<>();
    var it = open.values().iterator();
    while (it.hasNext()) {
      Open o = it.next();
      int t = o.info().timeoutSeconds();
      if (t > 0 && nowMs - o.openedMs() >= t * 1000L) {
        it.remove();
        done.add(new Done(o.id(), -1, o.info().timeoutString()));
      }
    }
    return done;
  }

  /** The open popups, oldest first. */
  List<Open> open() {
    return List.copyOf(open.values());
  }
}
