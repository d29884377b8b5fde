package org.jaria.net.data;

import java.util.Objects;

/**
 * What a popup shows and what its buttons mean (ArNetworking's {@code ArServerHandlerPopupInfo}). A
 * button with an empty label is not shown; the "pressed" texts are what the server tells every
 * client when the popup closes because of that button.
 *
 * @param ignoreIdentifier a key a client may use to let its user ignore popups of this kind
 * @param title the window's title
 * @param message the text
 * @param popupType the icon
 * @param defaultButton the button Enter presses (0..2)
 * @param escapeButton the button Escape presses (0..2)
 * @param timeoutSeconds seconds after which the popup closes by itself (0: never)
 * @param timeoutString what clients are told when it times out
 * @param button0Label the first button's label
 * @param button0Pressed what clients are told when it was pressed
 * @param button1Label the second button's label ("" for none)
 * @param button1Pressed what clients are told when it was pressed
 * @param button2Label the third button's label ("" for none)
 * @param button2Pressed what clients are told when it was pressed
 */
public record PopupInfo(
    String ignoreIdentifier,
    String title,
    String message,
    PopupType popupType,
    int defaultButton,
    int escapeButton,
    int timeoutSeconds,
    String timeoutString,
    String button0Label,
    String button0Pressed,
    String button1Label,
    String button1Pressed,
    String button2Label,
    String button2Pressed) {

  /** ArNetworking's popup icons, numbered as on the wire. */
  public enum PopupType {
    /** No icon (0). */
    NOICON,
    /** Information (1). */
    INFORMATION,
    /** A warning (2). */
    WARNING,
    /** A critical error (3). */
    CRITICAL,
    /** A question (4). */
    QUESTION;

    /** The type numbered {@code n} on the wire. */
    public static PopupType of(int n) {
      PopupType[] all = values();
      if (n < 0 || n >= all.length) {
        throw new IllegalArgumentException("a popup type is 0..4, not " + n);
      }
      return all[n];
    }
  }

  /** Checks the fields; null texts become empty, as in ArNetworking. */
  public PopupInfo {
    ignoreIdentifier = Objects.toString(ignoreIdentifier, "");
    title = Objects.toString(title, "");
    message = Objects.toString(message, "");
    Objects.requireNonNull(popupType, "popupType");
    timeoutString = Objects.toString(timeoutString, "");
    button0Label = Objects.toString(button0Label, "");
    button0Pressed = Objects.toString(button0Pressed, "");
    button1Label = Objects.toString(button1Label, "");
    button1Pressed = Objects.toString(button1Pressed, "");
    button2Label = Objects.toString(button2Label, "");
    button2Pressed = Objects.toString(button2Pressed, "");
    if (defaultButton < 0 || defaultButton > 2 || escapeButton < 0 || escapeButton > 2) {
      throw new IllegalArgumentException(
          "default and escape buttons are 0..2, not " + defaultButton + " and " + escapeButton);
    }
    if (timeoutSeconds < 0) {
      throw new IllegalArgumentException("a timeout is 0 (none) or more seconds");
    }
  }

  /** A popup with one button, "OK", that never times out. */
  public static PopupInfo message(String title, String message, PopupType type) {
    return new PopupInfo("", title, message, type, 0, 0, 0, "", "OK", "Closed", "", "", "", "");
  }

  /** What clients are told when button {@code button} was pressed. */
  public String pressedText(int button) {
    return switch (button) {
      case 0 -> button0Pressed;
      case 1 -> button1Pressed;
      case 2 -> button2Pressed;
      default -> "Popup closed because of odd click";
    };
  }
}
