package org.jaria.apps.eztrain;

import java.util.Locale;
import javafx.geometry.Insets;
import javafx.geometry.Pos;
import javafx.scene.Node;
import javafx.scene.control.Button;
import javafx.scene.control.Label;
import javafx.scene.control.RadioButton;
import javafx.scene.control.Spinner;
import javafx.scene.control.TextField;
import javafx.scene.control.TitledPane;
import javafx.scene.control.ToggleButton;
import javafx.scene.control.ToggleGroup;
import javafx.scene.control.Tooltip;
import javafx.scene.layout.GridPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.VBox;
import org.jaria.acts.color.ChannelBank;

/**
 * The EZ-Train console (thesis §5.3.22–24): channel bank and channel buttons, tracked-blob count,
 * channel file name with load and save, the training tools, undo and clear, magnification, view
 * mode and frame grabbing.
 */
final class ConsolePane extends VBox {

  private final EzTrainState state;
  private final ToggleGroup bankGroup = new ToggleGroup();
  private final ToggleGroup channelGroup = new ToggleGroup();
  private final RadioButton[] channelButtons = new RadioButton[8];
  private int page;
  private int trainedMask = -1;

  ConsolePane(EzTrainState state, EzTrainWindow w) {
    this.state = state;
    setSpacing(6);
    setPadding(new Insets(6));
    setPrefWidth(300);

    // ---- channels
    HBox banks = new HBox(2);
    String[] names = {"1–8", "9–16", "17–24", "25–32"};
    for (int b = 0; b < 4; b++) {
      ToggleButton t = new ToggleButton(names[b]);
      t.setId("bank-" + (b + 1));
      t.setToggleGroup(bankGroup);
      int page0 = b;
      t.setOnAction(
          e -> {
            t.setSelected(true);
            showPage(page0);
          });
      banks.getChildren().add(t);
    }
    GridPane channels = new GridPane();
    channels.setHgap(8);
    channels.setVgap(4);
    for (int i = 0; i < 8; i++) {
      RadioButton r = new RadioButton();
      r.setId("channel-btn-" + (i + 1));
      r.setToggleGroup(channelGroup);
      int slot = i;
      r.setOnAction(e -> state.channel.set(page * 8 + slot + 1));
      channelButtons[i] = r;
      channels.add(r, i % 4, i / 4);
    }
    Spinner<Integer> tracked = new Spinner<>(1, ChannelBank.MAX_TRACKED_BLOBS, 3);
    tracked.setId("tracked-blobs");
    tracked.setPrefWidth(70);
    tracked.valueProperty().addListener((o, a, b) -> state.trackedBlobs.set(b));
    state.trackedBlobs.addListener((o, a, b) -> tracked.getValueFactory().setValue(b.intValue()));
    TextField file = new TextField();
    file.setId("channel-file");
    file.setPrefColumnCount(12);
    file.textProperty().bindBidirectional(state.fileName);
    file.setOnAction(e -> w.files().channelFileEntered());
    Button browse =
        button(
            "…", "channel-browse", "Choose a channel file to load", w.files()::loadChannelDialog);
    Button load =
        button(
            "Load",
            "channel-load",
            "Load the file named above into the channel",
            w.files()::loadChannelByName);
    Button save =
        button(
            "Save",
            "channel-save",
            "Save the channel to the file named above",
            w.files()::saveChannel);
    VBox channelBox =
        new VBox(
            6,
            banks,
            channels,
            row(new Label("Blobs tracked"), tracked),
            row(new Label("Channel file"), file, browse),
            row(load, save));
    TitledPane channelPane = titled("Channel", channelBox);

    // ---- tools
    ToggleGroup toolGroup = new ToggleGroup();
    HBox tools = new HBox(2);
    for (TrainTool t : TrainTool.values()) {
      ToggleButton b = new ToggleButton(t.label());
      b.setId("tool-" + t.name().toLowerCase(Locale.ROOT));
      b.setToggleGroup(toolGroup);
      b.setTooltip(new Tooltip(t.label() + " (key " + t.key().getName() + ")"));
      b.setOnAction(
          e -> {
            b.setSelected(true);
            state.tool.set(t);
          });
      b.setSelected(state.tool.get() == t);
      state.tool.addListener((o, was, now) -> b.setSelected(now == t));
      tools.getChildren().add(b);
    }
    Button undo = button("Undo", "undo", "Undo the channel's last change (Ctrl+Z)", w::undo);
    Button clear =
        button("Clear training", "clear-training", "Empty the channel", w::clearTraining);
    TitledPane toolPane = titled("Training tools", new VBox(6, tools, row(undo, clear)));

    // ---- training window commands
    Spinner<Integer> mag = new Spinner<>(1, 6, state.magnification.get());
    mag.setId("magnification");
    mag.setPrefWidth(70);
    mag.valueProperty().addListener((o, a, b) -> state.magnification.set(b));
    state.magnification.addListener((o, a, b) -> mag.getValueFactory().setValue(b.intValue()));
    ToggleGroup viewGroup = new ToggleGroup();
    HBox views = new HBox(6);
    for (ViewMode m : ViewMode.values()) {
      RadioButton r = new RadioButton(m.label());
      r.setId("view-" + m.name().toLowerCase(Locale.ROOT));
      r.setToggleGroup(viewGroup);
      r.setSelected(state.viewMode.get() == m);
      r.setOnAction(e -> state.viewMode.set(m));
      state.viewMode.addListener((o, was, now) -> r.setSelected(now == m));
      views.getChildren().add(r);
    }
    ToggleGroup grabGroup = new ToggleGroup();
    RadioButton continuous = new RadioButton("Continuous");
    continuous.setId("grab-continuous");
    RadioButton single = new RadioButton("Single frame");
    single.setId("grab-single");
    continuous.setToggleGroup(grabGroup);
    single.setToggleGroup(grabGroup);
    continuous.setSelected(state.continuous.get());
    single.setSelected(!state.continuous.get());
    continuous.setOnAction(e -> state.continuous.set(true));
    single.setOnAction(e -> state.continuous.set(false));
    Button grab =
        button("Grab frame", "grab-frame", "Read one frame (single-frame mode)", w::grabFrame);
    grab.disableProperty().bind(state.continuous);
    TitledPane viewPane =
        titled(
            "Training window",
            new VBox(
                6, row(new Label("Magnification"), mag), views, row(continuous, single, grab)));

    getChildren().addAll(channelPane, toolPane, viewPane);
    state.channel.addListener((o, a, b) -> showChannel(b.intValue()));
    showChannel(state.channel.get());
  }

  private static Button button(String text, String id, String tip, Runnable action) {
    Button b = new Button(text);
    b.setId(id);
    b.setTooltip(new Tooltip(tip));
    b.setOnAction(e -> action.run());
    return b;
  }

  private static HBox row(Node... nodes) {
    HBox h = new HBox(6, nodes);
    h.setAlignment(Pos.CENTER_LEFT);
    return h;
  }

  private static TitledPane titled(String title, Node content) {
    TitledPane t = new TitledPane(title, content);
    t.setCollapsible(false);
    return t;
  }

  private void showChannel(int channel) {
    showPage((channel - 1) / 8);
  }

  private void showPage(int p) {
    page = p;
    bankGroup.getToggles().get(p).setSelected(true);
    for (int i = 0; i < 8; i++) {
      int c = p * 8 + i + 1;
      channelButtons[i].setText(Integer.toString(c));
      channelButtons[i].setSelected(c == state.channel.get());
    }
    markTrained(trainedMask);
  }

  /** Shows which channels hold training (bold), bit c-1 = channel c. */
  void markTrained(int mask) {
    trainedMask = mask;
    for (int i = 0; i < 8; i++) {
      int c = page * 8 + i + 1;
      boolean on = (mask & (1 << (c - 1))) != 0;
      channelButtons[i].setStyle(on ? "-fx-font-weight: bold; -fx-text-fill: #1a6e2a;" : "");
    }
  }
}
