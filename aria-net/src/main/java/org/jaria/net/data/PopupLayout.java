package org.jaria.net.data;

import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;

/**
 * ArNetworking's popup layouts ({@code ArServerHandlerPopup}), written and read:
 *
 * <ul>
 *   <li>{@code popupCreate} (server to client): byte4 id; string ignore identifier; string title;
 *       string message; byte type (0..4); string three button labels; byte default button; byte
 *       escape button. {@code popupList} answers with the open popups' {@code popupCreate} packets
 *       and then an empty {@code popupList} packet.
 *   <li>{@code popupClose} (server to client): byte4 id; string what to show.
 *   <li>{@code popupClicked} (client to server): byte4 id; byte button.
 * </ul>
 */
public final class PopupLayout {

  private PopupLayout() {}

  /**
   * A popup as a client sees it.
   *
   * @param id the server's number for it
   * @param ignoreIdentifier a key for ignoring popups of this kind
   * @param title the title
   * @param message the text
   * @param type the icon
   * @param buttons the three labels ("" for a button not shown)
   * @param defaultButton the button Enter presses
   * @param escapeButton the button Escape presses
   */
  public record Shown(
      int id,
      String ignoreIdentifier,
      String title,
      String message,
      PopupInfo.PopupType type,
      List<String> buttons,
      int defaultButton,
      int escapeButton) {

    /** Copies the labels. */
    public Shown {
      buttons = List.copyOf(buttons);
    }
  }

  /**
   * A popup closed, and why.
   *
   * @param id the popup's number
   * @param message what to show: the pressed button's text, the timeout text, or the server's
   */
  public record Closed(int id, String message) {}

  /** Writes a {@code popupCreate} packet. */
  public static void writeCreate(ArNetPacket out, int id, PopupInfo p) {
    out.byte4ToBuf(id)
        .strToBuf(p.ignoreIdentifier())
        .strToBuf(p.title())
        .strToBuf(p.message())
        .byteToBuf(p.popupType().ordinal())
        .strToBuf(p.button0Label())
        .strToBuf(p.button1Label())
        .strToBuf(p.button2Label())
        .byteToBuf(p.defaultButton())
        .byteToBuf(p.escapeButton());
  }

  /**
   * Reads a {@code popupCreate} packet.
   *
   * @return the popup, or null for an empty packet
   * @throws ArNetPacketException if it is cut short or its type is not 0..4
   */
  public static Shown readCreate(ArNetPacket in) {
    if (!in.hasMore()) {
      return null;
    }
    int id = in.bufToByte4();
    String ignore = in.bufToStr();
    String title = in.bufToStr();
    String message = in.bufToStr();
    int type = in.bufToByte();
    if (type < 0 || type > 4) {
      throw new ArNetPacketException("a popup type is 0..4, not " + type);
    }
    List<String> buttons = List.of(in.bufToStr(), in.bufToStr(), in.bufToStr());
    int def = in.bufToByte();
    int esc = in.bufToByte();
    return new Shown(id, ignore, title, message, PopupInfo.PopupType.of(type), buttons, def, esc);
  }

  /** Writes a {@code popupClose} packet. */
  public static void writeClose(ArNetPacket out, int id, String message) {
    out.byte4ToBuf(id).strToBuf(message);
  }

  /** Reads a {@code popupClose} packet. */
  public static Closed readClose(ArNetPacket in) {
    return new Closed(in.bufToByte4(), in.bufToStr());
  }

  /** Writes a {@code popupClicked} request's arguments. */
  public static void writeClicked(ArNetPacket out, int id, int button) {
    out.byte4ToBuf(id).byteToBuf(button);
  }
}
