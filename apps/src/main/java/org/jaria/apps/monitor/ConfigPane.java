package org.jaria.apps.monitor;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import javafx.beans.property.ReadOnlyStringWrapper;
import javafx.collections.FXCollections;
import javafx.collections.ObservableList;
import javafx.geometry.Insets;
import javafx.scene.control.Button;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.control.TableColumn;
import javafx.scene.control.TableView;
import javafx.scene.control.cell.TextFieldTableCell;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.HBox;
import org.jaria.net.data.ConfigParam;
import org.jaria.net.data.ConfigSection;

/**
 * The robot program's configuration (ArConfig) as a table per section: edit values in place, then
 * Apply sends the changed ones with {@code setConfig}; the server checks each and its first refusal
 * is shown. The table refreshes from the configuration the monitor fetches after each Apply unless
 * edits are pending.
 */
final class ConfigPane extends BorderPane {

  /** One row: a parameter and the value typed for it. */
  static final class Row {
    final String section;
    final ConfigParam param;
    String edited;

    Row(String section, ConfigParam param) {
      this.section = section;
      this.param = param;
      this.edited = param.value();
    }

    boolean changed() {
      return !edited.equals(param.value());
    }
  }

  private final ComboBox<String> sections = new ComboBox<>();
  private final TableView<Row> table = new TableView<>();
  private final Button apply = new Button("Apply");
  private final Button revert = new Button("Revert");
  private final Label message = new Label("");
  private final Map<String, List<Row>> rows = new LinkedHashMap<>();
  private List<ConfigSection> shown;

  /** A pane that sends [[section, name, value]...] to {@code send} on Apply. */
  ConfigPane(Consumer<List<List<String>>> send) {
    setId("config");
    sections.setId("config-section");
    table.setId("config-table");
    apply.setId("config-apply");
    revert.setId("config-revert");
    message.setId("config-message");
    message.setWrapText(true);
    table.setEditable(true);
    TableColumn<Row, String> name = new TableColumn<>("Parameter");
    name.setCellValueFactory(c -> new ReadOnlyStringWrapper(c.getValue().param.name()));
    TableColumn<Row, String> value = new TableColumn<>("Value");
    value.setId("config-value");
    value.setCellValueFactory(c -> new ReadOnlyStringWrapper(c.getValue().edited));
    value.setCellFactory(TextFieldTableCell.forTableColumn());
    value.setOnEditCommit(
        e -> {
          e.getRowValue().edited = e.getNewValue().strip();
          updateButtons();
        });
    value.setEditable(true);
    TableColumn<Row, String> range = new TableColumn<>("Range");
    range.setCellValueFactory(
        c -> {
          ConfigParam p = c.getValue().param;
          return new ReadOnlyStringWrapper(
              p.min().isEmpty() && p.max().isEmpty() ? "" : p.min() + " .. " + p.max());
        });
    TableColumn<Row, String> desc = new TableColumn<>("Description");
    desc.setCellValueFactory(c -> new ReadOnlyStringWrapper(c.getValue().param.description()));
    name.setPrefWidth(150);
    value.setPrefWidth(90);
    range.setPrefWidth(100);
    desc.setPrefWidth(260);
    table.getColumns().add(name);
    table.getColumns().add(value);
    table.getColumns().add(range);
    table.getColumns().add(desc);
    sections.setOnAction(e -> showSection());
    apply.setOnAction(
        e -> {
          List<List<String>> changes = new ArrayList<>();
          for (List<Row> l : rows.values()) {
            for (Row r : l) {
              if (r.changed()) {
                changes.add(List.of(r.section, r.param.name(), r.edited));
              }
            }
          }
          if (!changes.isEmpty()) {
            message.setText("Sending " + changes.size() + " change(s)...");
            send.accept(changes);
          }
        });
    revert.setOnAction(
        e -> {
          for (List<Row> l : rows.values()) {
            for (Row r : l) {
              r.edited = r.param.value();
            }
          }
          table.refresh();
          updateButtons();
        });
    HBox top = new HBox(8, new Label("Section"), sections, apply, revert);
    top.setPadding(new Insets(6));
    setTop(top);
    setCenter(table);
    setBottom(message);
    BorderPane.setMargin(message, new Insets(4, 6, 4, 6));
    updateButtons();
  }

  /** Shows the server's configuration, unless the operator has edits not applied yet. */
  void show(List<ConfigSection> config) {
    if (config == null || config.equals(shown) || pending()) {
      return;
    }
    shown = config;
    String selected = sections.getValue();
    rows.clear();
    for (ConfigSection s : config) {
      List<Row> l = new ArrayList<>();
      for (ConfigParam p : s.params()) {
        l.add(new Row(s.name(), p));
      }
      rows.put(s.name(), l);
    }
    sections.getItems().setAll(rows.keySet());
    sections.setValue(
        selected != null && rows.containsKey(selected)
            ? selected
            : rows.isEmpty() ? null : rows.keySet().iterator().next());
    showSection();
  }

  /** Reports the server's answer to Apply. */
  void applied(List<String> refusals) {
    if (refusals.isEmpty()) {
      message.setText("Applied.");
    } else {
      message.setText(String.join("\n", refusals));
    }
    // Take the server's values as they now are.
    for (List<Row> l : rows.values()) {
      for (Row r : l) {
        r.edited = r.param.value();
      }
    }
    shown = null;
    updateButtons();
  }

  /** The message under the table. */
  String message() {
    return message.getText();
  }

  private boolean pending() {
    return rows.values().stream().flatMap(List::stream).anyMatch(Row::changed);
  }

  private void showSection() {
    ObservableList<Row> l =
        FXCollections.observableArrayList(rows.getOrDefault(sections.getValue(), List.of()));
    table.setItems(l);
  }

  private void updateButtons() {
    boolean p = pending();
    apply.setDisable(!p);
    revert.setDisable(!p);
  }

  /** Sets a parameter's edited value as if typed (for tests and scripting). */
  boolean edit(String section, String name, String value) {
    for (Row r : rows.getOrDefault(section, List.of())) {
      if (r.param.name().equals(name)) {
        r.edited = value;
        table.refresh();
        updateButtons();
        return true;
      }
    }
    return false;
  }
}
