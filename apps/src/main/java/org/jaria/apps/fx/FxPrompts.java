package org.jaria.apps.fx;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import javafx.scene.control.Alert;
import javafx.scene.control.ButtonBar;
import javafx.scene.control.ButtonType;
import javafx.scene.control.ListView;
import javafx.scene.control.TextArea;
import javafx.scene.control.TextInputDialog;
import javafx.scene.layout.Region;
import javafx.scene.layout.VBox;
import javafx.stage.FileChooser;
import javafx.stage.Window;

/** {@link Prompts} as JavaFX dialogs owned by a window. Call on the JavaFX thread. */
public final class FxPrompts implements Prompts {

  private final Window owner;

  /** Dialogs centred on {@code owner} (may be null). */
  public FxPrompts(Window owner) {
    this.owner = owner;
  }

  @Override
  public void error(String title, String message) {
    Alert a = new Alert(Alert.AlertType.ERROR);
    a.initOwner(owner);
    a.setTitle(title);
    a.setHeaderText(title);
    // A TextArea lets the user select and copy long messages (file names, line numbers).
    TextArea text = new TextArea(message);
    text.setEditable(false);
    text.setWrapText(true);
    text.setPrefRowCount(Math.min(12, 2 + message.length() / 60));
    a.getDialogPane().setContent(text);
    a.showAndWait();
  }

  @Override
  public void info(String title, String text) {
    Alert a = new Alert(Alert.AlertType.INFORMATION);
    a.initOwner(owner);
    a.setTitle(title);
    a.setHeaderText(title);
    TextArea area = new TextArea(text);
    area.setEditable(false);
    area.setStyle("-fx-font-family: monospace;");
    area.setPrefRowCount(Math.min(24, (int) text.lines().count() + 1));
    area.setPrefColumnCount(columnsFor(text));
    a.getDialogPane().setContent(area);
    a.getDialogPane().setMinWidth(Region.USE_PREF_SIZE);
    a.setResizable(true);
    a.showAndWait();
  }

  /**
   * How many columns a text box needs to show {@code text} without cutting lines off on the right
   * (its longest line and a margin), within what fits on a screen.
   */
  static int columnsFor(String text) {
    int longest = text.lines().mapToInt(String::length).max().orElse(0);
    return Math.max(40, Math.min(120, longest + 4));
  }

  @Override
  public boolean confirm(String title, String question) {
    Alert a = new Alert(Alert.AlertType.CONFIRMATION, question, ButtonType.OK, ButtonType.CANCEL);
    a.initOwner(owner);
    a.setTitle(title);
    a.setHeaderText(title);
    return a.showAndWait().filter(b -> b == ButtonType.OK).isPresent();
  }

  @Override
  public Optional<String> askText(String title, String prompt, String initial) {
    TextInputDialog d = new TextInputDialog(initial);
    d.initOwner(owner);
    d.setTitle(title);
    d.setHeaderText(prompt);
    return d.showAndWait();
  }

  @Override
  public Optional<Path> chooseOpenFile(String title, List<String> filters, Path initialDir) {
    File f = chooser(title, filters, initialDir, null).showOpenDialog(owner);
    return Optional.ofNullable(f).map(File::toPath);
  }

  @Override
  public Optional<Path> chooseSaveFile(
      String title, List<String> filters, Path initialDir, String initialName) {
    File f = chooser(title, filters, initialDir, initialName).showSaveDialog(owner);
    return Optional.ofNullable(f).map(File::toPath);
  }

  @Override
  public boolean confirmProblems(
      String title, String header, List<String> problems, String goOnLabel) {
    Alert a = new Alert(Alert.AlertType.WARNING);
    a.initOwner(owner);
    a.setTitle(title);
    a.setHeaderText(header);
    ListView<String> list = new ListView<>();
    list.getItems().setAll(problems);
    list.setPrefHeight(Math.min(300, 28 + 24.0 * problems.size()));
    a.getDialogPane().setContent(new VBox(list));
    ButtonType goOn = new ButtonType(goOnLabel, ButtonBar.ButtonData.OK_DONE);
    a.getButtonTypes().setAll(goOn, ButtonType.CANCEL);
    return a.showAndWait().filter(b -> b == goOn).isPresent();
  }

  private static FileChooser chooser(
      String title, List<String> filters, Path initialDir, String initialName) {
    FileChooser c = new FileChooser();
    c.setTitle(title);
    for (String f : filters) {
      int bar = f.indexOf('|');
      String desc = bar < 0 ? f : f.substring(0, bar);
      String pats = bar < 0 ? f : f.substring(bar + 1);
      c.getExtensionFilters()
          .add(new FileChooser.ExtensionFilter(desc, Arrays.asList(pats.split("\\s+"))));
    }
    if (initialDir != null && Files.isDirectory(initialDir)) {
      c.setInitialDirectory(initialDir.toFile());
    }
    if (initialName != null) {
      c.setInitialFileName(initialName);
    }
    return c;
  }
}
