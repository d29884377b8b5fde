package org.jaria.apps.eztrain;

import javafx.beans.property.BooleanProperty;
import javafx.beans.property.IntegerProperty;
import javafx.beans.property.ObjectProperty;
import javafx.beans.property.SimpleBooleanProperty;
import javafx.beans.property.SimpleIntegerProperty;
import javafx.beans.property.SimpleObjectProperty;
import javafx.beans.property.SimpleStringProperty;
import javafx.beans.property.StringProperty;

/**
 * The EZ-Train console's settings as JavaFX properties: the console's controls and the menus bind
 * to them, and {@link EzTrainWindow} acts when they change. JavaFX thread only.
 */
final class EzTrainState {

  /** The selected channel, 1..32. */
  final IntegerProperty channel = new SimpleIntegerProperty(1);

  /** How many blobs the selected channel tracks, 1..10. */
  final IntegerProperty trackedBlobs = new SimpleIntegerProperty(3);

  /** The selected channel's file name. */
  final StringProperty fileName = new SimpleStringProperty("channel1.lut");

  /** The training tool. */
  final ObjectProperty<TrainTool> tool = new SimpleObjectProperty<>(TrainTool.ADD);

  /** The view mode. */
  final ObjectProperty<ViewMode> viewMode = new SimpleObjectProperty<>(ViewMode.OVERLAY);

  /** Colour of the channel's pixels in Overlay mode. */
  final ObjectProperty<MarkColor> threshColor = new SimpleObjectProperty<>(MarkColor.BLUE);

  /** Colour of the tools' rectangle and brush. */
  final ObjectProperty<MarkColor> drawColor = new SimpleObjectProperty<>(MarkColor.RED);

  /** Magnification of the training image, 1..6. */
  final IntegerProperty magnification = new SimpleIntegerProperty(3);

  /** Draw/Erase brush size, 1..9 (odd). */
  final IntegerProperty brush = new SimpleIntegerProperty(1);

  /** Continuous (true) or single-frame (false) grabbing of live video. */
  final BooleanProperty continuous = new SimpleBooleanProperty(true);
}
