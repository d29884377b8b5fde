package org.jaria.apps.eztrain;

import javafx.scene.input.KeyCode;

/**
 * EZ-Train's training tools (thesis §5.3.15), each with the key that selects it while the mouse is
 * over the training image.
 */
public enum TrainTool {
  /** Drag a rectangle: its colours (and neighbouring ones) join the channel. */
  ADD("Add", KeyCode.A),
  /** Drag a rectangle: its colours (and neighbouring ones) leave the channel. */
  REMOVE("Remove", KeyCode.R),
  /** Paint with the brush: the exact colours under it join the channel. */
  DRAW("Draw", KeyCode.D),
  /** Paint with the brush: the exact colours under it leave the channel. */
  ERASE("Erase", KeyCode.E),
  /** Click a pixel: its RGB values are printed in the output area. */
  PICK("Pick", KeyCode.P);

  private final String label;
  private final KeyCode key;

  TrainTool(String label, KeyCode key) {
    this.label = label;
    this.key = key;
  }

  /** The name on the button. */
  public String label() {
    return label;
  }

  /** The shortcut key. */
  public KeyCode key() {
    return key;
  }
}
