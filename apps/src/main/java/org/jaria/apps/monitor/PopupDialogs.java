package org.jaria.apps.monitor;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiConsumer;
import javafx.scene.control.Alert;
import javafx.scene.control.ButtonBar;
import javafx.scene.control.ButtonType;
import javafx.stage.Modality;
import javafx.stage.Window;
import org.jaria.net.data.PopupLayout;

/**
 * Shows the server's popups (ArServerHandlerPopup) as dialogs that do not block the window: one per
 * open popup, with the popup's buttons; pressing one tells the server ({@code popupClicked}), and a
 * popup the server closed (a click on another monitor, a timeout) closes here too. JavaFX thread
 * only.
 */
final class PopupDialogs {

  private final Window owner;
  private final BiConsumer<Integer, Integer> clicked;
  private final Map<Integer, Alert> shown = new HashMap<>();

  /**
   * @param clicked told (popup number, button) when the user presses a button
   */
  PopupDialogs(Window owner, BiConsumer<Integer, Integer> clicked) {
    this.owner = owner;
    this.clicked = clicked;
  }

  /** Opens dialogs for new popups and closes those no longer open. */
  void show(Map<Integer, PopupLayout.Shown> open) {
    for (var it = shown.entrySet().iterator(); it.hasNext(); ) {
      var e = it.next();
      if (!open.containsKey(e.getKey())) {
        it.remove();
        e.getValue().setOnHidden(null);
        e.getValue().close();
      }
    }
    for (PopupLayout.Shown p : open.values()) {
      if (!shown.containsKey(p.id())) {
        shown.put(p.id(), dialog(p));
      }
    }
  }

  /** How many dialogs are showing (for tests). */
  int count() {
    return shown.size();
  }

  private Alert dialog(PopupLayout.Shown p) {
    Alert a = new Alert(type(p.type()));
    a.initOwner(owner);
    a.initModality(Modality.NONE);
    a.setTitle(p.title());
    a.setHeaderText(p.title());
    a.setContentText(p.message());
    a.getButtonTypes().clear();
    List<String> labels = p.buttons();
    for (int i = 0; i < labels.size(); i++) {
      if (!labels.get(i).isEmpty()) {
        ButtonBar.ButtonData data =
            i == p.defaultButton()
                ? ButtonBar.ButtonData.OK_DONE
                : i == p.escapeButton()
                    ? ButtonBar.ButtonData.CANCEL_CLOSE
                    : ButtonBar.ButtonData.OTHER;
        a.getButtonTypes().add(new ButtonType(labels.get(i), data));
      }
    }
    if (a.getButtonTypes().isEmpty()) {
      a.getButtonTypes().add(new ButtonType("OK", ButtonBar.ButtonData.CANCEL_CLOSE));
    }
    a.setOnHidden(
        e -> {
          shown.remove(p.id());
          int button =
              a.getResult() == null ? p.escapeButton() : labels.indexOf(a.getResult().getText());
          clicked.accept(p.id(), button < 0 ? p.escapeButton() : button);
        });
    a.show();
    return a;
  }

  private static Alert.AlertType type(org.jaria.net.data.PopupInfo.PopupType t) {
    return switch (t) {
      case NOICON -> Alert.AlertType.NONE;
      case INFORMATION -> Alert.AlertType.INFORMATION;
      case WARNING -> Alert.AlertType.WARNING;
      case CRITICAL -> Alert.AlertType.ERROR;
      case QUESTION -> Alert.AlertType.CONFIRMATION;
    };
  }
}
