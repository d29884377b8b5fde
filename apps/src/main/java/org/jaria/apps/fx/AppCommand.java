package org.jaria.apps.fx;

import javafx.stage.Stage;

/**
 * A picocli command that opens a desktop app. After picocli has filled in the options, {@link
 * #open} builds the app in a stage; {@link AppLauncher} runs it until its window closes, and {@code
 * jaria screenshot} renders it to a PNG file instead.
 */
public interface AppCommand {

  /** The app's name on the command line ("mapper", "eztrain", "simview"). */
  String appName();

  /**
   * Builds the app in {@code stage} and shows it (JavaFX thread).
   *
   * @throws Exception if it cannot start (the message says why and what to do)
   */
  DesktopApp open(Stage stage, AppEnvironment env) throws Exception;
}
