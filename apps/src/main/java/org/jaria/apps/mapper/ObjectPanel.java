package org.jaria.apps.mapper;

import java.util.Locale;
import java.util.Optional;
import javafx.geometry.Insets;
import javafx.scene.control.Button;
import javafx.scene.control.Label;
import javafx.scene.control.TextField;
import javafx.scene.layout.GridPane;
import javafx.scene.layout.Region;
import javafx.scene.layout.VBox;
import org.jaria.apps.fx.Prompts;
import org.jaria.map.ArMapObject;

/**
 * The side panel showing the selected object: its type, position, and its name and heading, which
 * can be edited here (Enter or Apply), each change one undoable step.
 */
final class ObjectPanel extends VBox {

  private final MapDocument[] document;
  private final MapSelection selection;
  private final Prompts prompts;
  private final Label type = new Label("Nothing selected");
  private final Label position = new Label("");
  private final TextField name = new TextField();
  private final TextField heading = new TextField();
  private final Button apply = new Button("Apply");
  private long shown = -1;

  /**
   * A panel for the document in {@code document[0]} (an array so the window can swap documents).
   */
  ObjectPanel(MapDocument[] document, MapSelection selection, Prompts prompts) {
    this.document = document;
    this.selection = selection;
    this.prompts = prompts;
    setSpacing(8);
    setPadding(new Insets(10));
    setPrefWidth(240);
    setMinWidth(200);
    name.setId("object-name");
    heading.setId("object-heading");
    apply.setId("object-apply");
    type.setStyle("-fx-font-weight: bold");
    GridPane g = new GridPane();
    g.setHgap(6);
    g.setVgap(6);
    g.addRow(0, fixed("Name"), name);
    g.addRow(1, fixed("Heading°"), heading);
    getChildren().addAll(type, position, g, apply);
    apply.setOnAction(e -> applyEdits());
    name.setOnAction(e -> applyEdits());
    heading.setOnAction(e -> applyEdits());
    selection.addListener(this::refresh);
    refresh();
  }

  private static Label fixed(String text) {
    Label l = new Label(text);
    l.setMinWidth(Region.USE_PREF_SIZE);
    return l;
  }

  /** Shows the current selection (also after the document changed). */
  void refresh() {
    Optional<MapObjectEntry> e = selected();
    boolean on = e.isPresent();
    name.setDisable(!on);
    heading.setDisable(!on);
    apply.setDisable(!on);
    if (!on) {
      shown = -1;
      int n = selection.size();
      type.setText(n == 0 ? "Nothing selected" : n + " selected");
      position.setText("");
      name.setText("");
      heading.setText("");
      return;
    }
    ArMapObject o = e.get().object();
    double[] c = MapGeometry.center(o);
    type.setText(ObjectKind.describe(o.type()));
    position.setText(String.format(Locale.ROOT, "x %.0f mm, y %.0f mm", c[0], c[1]));
    if (shown != e.get().id() || !name.isFocused()) {
      name.setText(o.name());
    }
    if (shown != e.get().id() || !heading.isFocused()) {
      heading.setText(String.format(Locale.ROOT, "%.1f", o.pose().th()));
    }
    shown = e.get().id();
  }

  private Optional<MapObjectEntry> selected() {
    long id = selection.single();
    return id < 0 ? Optional.empty() : document[0].content().findObject(id);
  }

  private void applyEdits() {
    Optional<MapObjectEntry> e = selected();
    if (e.isEmpty()) {
      return;
    }
    ArMapObject o = e.get().object();
    double th;
    try {
      th = Double.parseDouble(heading.getText().trim().replace(',', '.'));
    } catch (NumberFormatException ex) {
      prompts.error(
          "Not a heading",
          "'" + heading.getText() + "' is not a number: type the heading in degrees, e.g. 90");
      return;
    }
    try {
      if (!name.getText().equals(o.name())) {
        document[0].execute(
            MapEdits.replace("Rename", e.get().id(), MapGeometry.renamed(o, name.getText())));
        o = document[0].content().findObject(e.get().id()).orElseThrow().object();
      }
      if (Math.abs(th - o.pose().th()) > 1e-9) {
        document[0].execute(
            MapEdits.replace("Rotate", e.get().id(), MapGeometry.withHeading(o, th)));
      }
    } catch (IllegalArgumentException ex) {
      prompts.error("Cannot change the object", ex.getMessage());
    }
    refresh();
  }
}
