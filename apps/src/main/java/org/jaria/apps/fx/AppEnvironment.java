package org.jaria.apps.fx;

import java.util.function.Function;
import javafx.stage.Window;

/**
 * What an app gets from whoever starts it: where its settings live and how it asks the user things.
 * The command line passes the user's settings and real dialogs; tests and {@code jaria screenshot}
 * pass in-memory settings and scripted answers.
 *
 * @param prefs the app's remembered settings
 * @param prompts makes the dialogs for a window
 * @param interactive false when nobody uses the window ({@code jaria screenshot}): apps then open
 *     no network ports and start no servers
 */
public record AppEnvironment(
    AppPrefs prefs, Function<Window, Prompts> prompts, boolean interactive) {

  /** The user's settings of {@code appName} and real dialogs. */
  public static AppEnvironment forUser(String appName) {
    return new AppEnvironment(AppPrefs.forApp(appName), FxPrompts::new, true);
  }

  /** In-memory settings and the given answers (tests). */
  public static AppEnvironment scripted(Prompts prompts) {
    return new AppEnvironment(AppPrefs.inMemory(), w -> prompts, true);
  }

  /** In-memory settings, collected errors, no ports or servers ({@code jaria screenshot}). */
  public static AppEnvironment headless(HeadlessPrompts prompts) {
    return new AppEnvironment(AppPrefs.inMemory(), w -> prompts, false);
  }

  /**
   * The environment for another app opened from this one (EZ-Train from the simulator view): the
   * same dialogs and interactivity, and that app's own settings — the user's settings of {@code
   * appName} if these are the user's, else a part of these kept apart by a key prefix.
   */
  public AppEnvironment forApp(String appName) {
    AppPrefs p =
        prefs instanceof AppPrefs.JavaPrefs
            ? AppPrefs.forApp(appName)
            : prefs.scoped(appName + ".");
    return new AppEnvironment(p, prompts, interactive);
  }
}
