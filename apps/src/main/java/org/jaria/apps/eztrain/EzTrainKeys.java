package org.jaria.apps.eztrain;

import javafx.event.EventHandler;
import javafx.scene.Scene;
import javafx.scene.control.TextInputControl;
import javafx.scene.input.KeyCode;
import javafx.scene.input.KeyEvent;

/**
 * EZ-Train's single keys, as ACTS has them: 1–4 (or the keypad) choose the view mode, each tool's
 * letter chooses the tool, Esc cancels a drag or quits. Keys typed into a text field are left
 * alone, and so are shortcuts with Ctrl/Cmd or Alt (the menus own those).
 */
final class EzTrainKeys implements EventHandler<KeyEvent> {

  private final EzTrainState state;
  private final TrainingPane training;
  private final Runnable quit;

  EzTrainKeys(EzTrainState state, TrainingPane training, Runnable quit) {
    this.state = state;
    this.training = training;
    this.quit = quit;
  }

  @Override
  public void handle(KeyEvent e) {
    Scene scene = e.getSource() instanceof Scene s ? s : null;
    if (e.getTarget() instanceof TextInputControl
        || (scene != null && scene.getFocusOwner() instanceof TextInputControl)) {
      return;
    }
    if (e.isShortcutDown() || e.isAltDown()) {
      return;
    }
    KeyCode k = e.getCode();
    if (k == KeyCode.ESCAPE) {
      if (training.dragging()) {
        training.cancel();
      } else {
        quit.run();
      }
      e.consume();
      return;
    }
    for (ViewMode m : ViewMode.values()) {
      if (k.getChar().equals(String.valueOf(m.key())) || k == numpad(m)) {
        state.viewMode.set(m);
        e.consume();
        return;
      }
    }
    for (TrainTool t : TrainTool.values()) {
      if (k == t.key()) {
        state.tool.set(t);
        e.consume();
        return;
      }
    }
  }

  private static KeyCode numpad(ViewMode m) {
    return KeyCode.valueOf("NUMPAD" + m.key());
  }
}
