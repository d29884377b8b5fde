package org.jaria.apps.eztrain;

import java.util.Locale;
import javafx.geometry.Insets;
import javafx.geometry.Pos;
import javafx.scene.control.Button;
import javafx.scene.control.Label;
import javafx.scene.control.Slider;
import javafx.scene.image.ImageView;
import javafx.scene.image.PixelFormat;
import javafx.scene.image.WritableImage;
import javafx.scene.layout.GridPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.VBox;
import org.jaria.acts.color.Channel;
import org.jaria.acts.color.ColorPlane;
import org.jaria.acts.color.PlaneLimits;

/**
 * Manual training (thesis §5.3.16): the selected channel's three colour planes drawn as images
 * (white: trained and allowed; grey: trained but removed by the limits; black: not trained), each
 * with its two colour-threshold sliders, the High Bright and Low Bright sliders, and Reset Limits,
 * Fill Plane and Clear Plane buttons.
 */
final class ManualTrainingPane extends VBox {

  /** The controls of one plane. */
  private final class PlaneControls {
    final ColorPlane plane;
    final ImageView view = new ImageView();
    final Slider first = new Slider(0, 90, 0);
    final Slider second = new Slider(0, 90, 0);
    final Slider high = new Slider(0, PlaneLimits.MAX_BRIGHT, PlaneLimits.MAX_BRIGHT);
    final Slider low = new Slider(0, PlaneLimits.MAX_BRIGHT, 0);
    WritableImage image;
    boolean updating;

    PlaneControls(ColorPlane plane) {
      this.plane = plane;
      String id = plane.name().toLowerCase(Locale.ROOT);
      view.setId("plane-" + id);
      view.setFitWidth(128);
      view.setFitHeight(128);
      view.setSmooth(false);
      first.setId("plane-" + id + "-first");
      second.setId("plane-" + id + "-second");
      high.setId("plane-" + id + "-high");
      low.setId("plane-" + id + "-low");
      for (Slider s : new Slider[] {first, second, high, low}) {
        s.setPrefWidth(110);
        s.valueChangingProperty()
            .addListener(
                (o, was, changing) -> {
                  if (!changing) {
                    commit();
                  }
                });
        // Clicks on the track and keyboard changes do not go through "changing".
        s.valueProperty()
            .addListener(
                (o, a, b) -> {
                  if (!s.isValueChanging()) {
                    commit();
                  }
                });
      }
    }

    PlaneLimits limits() {
      int lo = (int) Math.round(low.getValue());
      int hi = (int) Math.round(high.getValue());
      return new PlaneLimits(
          (int) Math.round(first.getValue()),
          (int) Math.round(second.getValue()),
          Math.min(lo, hi),
          Math.max(lo, hi));
    }

    void commit() {
      if (!updating) {
        window.setPlaneLimits(plane, limits());
      }
    }

    void show(PlaneLimits l) {
      updating = true;
      try {
        first.setValue(l.firstColor());
        second.setValue(l.secondColor());
        high.setValue(l.highBright());
        low.setValue(l.lowBright());
      } finally {
        updating = false;
      }
    }

    VBox build() {
      String id = plane.name().toLowerCase(Locale.ROOT);
      GridPane g = new GridPane();
      g.setHgap(6);
      g.setVgap(2);
      g.addRow(0, new Label(plane.firstName()), first);
      g.addRow(1, new Label(plane.secondName()), second);
      g.addRow(2, new Label("High bright"), high);
      g.addRow(3, new Label("Low bright"), low);
      Button reset = new Button("Reset limits");
      reset.setId("plane-" + id + "-reset");
      reset.setOnAction(e -> window.setPlaneLimits(plane, PlaneLimits.NONE));
      Button fill = new Button("Fill plane");
      fill.setId("plane-" + id + "-fill");
      fill.setOnAction(e -> window.fillPlane(plane));
      Button clear = new Button("Clear plane");
      clear.setId("plane-" + id + "-clear");
      clear.setOnAction(e -> window.clearPlane(plane));
      Label title = new Label(plane.firstName() + " / " + plane.secondName());
      title.setStyle("-fx-font-weight: bold");
      for (Button b : new Button[] {reset, fill, clear}) {
        b.setStyle("-fx-font-size: 0.85em;");
      }
      VBox controls = new VBox(3, title, g, new HBox(3, reset, fill, clear));
      HBox row = new HBox(8, view, controls);
      row.setAlignment(Pos.TOP_LEFT);
      return new VBox(row);
    }
  }

  private final EzTrainWindow window;
  private final PlaneControls[] planes = new PlaneControls[3];

  ManualTrainingPane(EzTrainWindow window) {
    this.window = window;
    setSpacing(8);
    setPadding(new Insets(6));
    for (ColorPlane p : ColorPlane.all()) {
      planes[p.ordinal()] = new PlaneControls(p);
      getChildren().add(planes[p.ordinal()].build());
    }
  }

  /** Shows the planes of a refresh and the channel's current limits. */
  void show(Rendered r, Channel channel) {
    if (r.planes() == null) {
      return;
    }
    int n = r.planeSize();
    for (PlaneControls pc : planes) {
      if (pc.image == null || (int) pc.image.getWidth() != n) {
        pc.image = new WritableImage(n, n);
        pc.view.setImage(pc.image);
      }
      pc.image
          .getPixelWriter()
          .setPixels(
              0, 0, n, n, PixelFormat.getIntArgbInstance(), r.planes()[pc.plane.ordinal()], 0, n);
      if (!isDragging(pc)) {
        pc.show(channel.getLimits(pc.plane));
      }
    }
  }

  private static boolean isDragging(PlaneControls pc) {
    return pc.first.isValueChanging()
        || pc.second.isValueChanging()
        || pc.high.isValueChanging()
        || pc.low.isValueChanging();
  }
}
