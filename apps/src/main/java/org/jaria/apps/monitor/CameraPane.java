package org.jaria.apps.monitor;

import java.io.ByteArrayInputStream;
import javafx.geometry.Pos;
import javafx.scene.control.Label;
import javafx.scene.image.Image;
import javafx.scene.image.ImageView;
import javafx.scene.image.PixelFormat;
import javafx.scene.image.WritableImage;
import javafx.scene.layout.StackPane;
import org.jaria.net.data.VideoFrame;

/** The robot's camera: shows the newest frame, scaled to the pane. JavaFX thread only. */
final class CameraPane extends StackPane {

  private final ImageView view = new ImageView();
  private final Label none = new Label("No camera on this robot.");
  private long shownSequence = -1;

  CameraPane() {
    setId("camera");
    view.setId("camera-image");
    view.setPreserveRatio(true);
    view.fitWidthProperty().bind(widthProperty().subtract(10));
    view.fitHeightProperty().bind(heightProperty().subtract(10));
    setAlignment(Pos.CENTER);
    getChildren().addAll(none, view);
  }

  /** Whether the server has a camera. */
  void setAvailable(boolean available) {
    none.setText(available ? "Waiting for a frame..." : "No camera on this robot.");
    none.setVisible(true);
    view.setImage(null);
    shownSequence = -1;
  }

  /** Shows {@code f} if it is new. */
  void show(VideoFrame f) {
    if (f == null || f.getSequence() == shownSequence) {
      return;
    }
    shownSequence = f.getSequence();
    Image img;
    if (f.getFormat() == VideoFrame.Format.RGB) {
      WritableImage w = new WritableImage(f.getWidth(), f.getHeight());
      w.getPixelWriter()
          .setPixels(
              0,
              0,
              f.getWidth(),
              f.getHeight(),
              PixelFormat.getByteRgbInstance(),
              f.getData(),
              0,
              f.getWidth() * 3);
      img = w;
    } else {
      img = new Image(new ByteArrayInputStream(f.getData()));
    }
    if (!img.isError()) {
      view.setImage(img);
      none.setVisible(false);
    }
  }

  /** The frame number shown, or -1. */
  long shownSequence() {
    return shownSequence;
  }
}
