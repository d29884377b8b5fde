package org.jaria.apps.fx;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

/**
 * Everything an app asks the user in a dialog: errors, confirmations, a line of text, files. The
 * windows talk to this interface instead of opening dialogs themselves, so tests (and {@code jaria
 * screenshot}) can answer without a modal dialog blocking them; {@link FxPrompts} is the real
 * implementation.
 */
public interface Prompts {

  /**
   * Tells the user something failed.
   *
   * @param title short title, e.g. "Cannot open map"
   * @param message what went wrong and what to do about it
   */
  void error(String title, String message);

  /**
   * Shows information the user asked for (Help → Keyboard Shortcuts). Does nothing unless
   * implemented, so older implementations keep working.
   *
   * @param title short title
   * @param text the information, one item a line
   */
  default void info(String title, String text) {}

  /** Asks a yes/no question; true for yes (or OK). */
  boolean confirm(String title, String question);

  /**
   * Asks for a line of text.
   *
   * @return the text, or empty if the user cancelled
   */
  Optional<String> askText(String title, String prompt, String initial);

  /**
   * Asks which file to open.
   *
   * @param filters file name patterns such as {@code "Map files|*.map"} (description, bar, patterns
   *     separated by spaces)
   * @param initialDir where to start, or null
   */
  Optional<Path> chooseOpenFile(String title, List<String> filters, Path initialDir);

  /** Asks where to save a file (see {@link #chooseOpenFile} for the filters). */
  Optional<Path> chooseSaveFile(
      String title, List<String> filters, Path initialDir, String initialName);

  /**
   * Shows a list of problems and asks whether to go on anyway.
   *
   * @return true to go on
   */
  boolean confirmProblems(String title, String header, List<String> problems, String goOnLabel);
}
