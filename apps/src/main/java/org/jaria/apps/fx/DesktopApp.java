package org.jaria.apps.fx;

import java.util.concurrent.CompletableFuture;
import javafx.stage.Stage;

/**
 * A running desktop app (map editor, EZ-Train, simulator view): its main window, a signal that its
 * content is shown, and a way to release what it holds (threads, servers, worlds).
 */
public interface DesktopApp extends AutoCloseable {

  /** The app's main window. */
  Stage stage();

  /**
   * Completes once the window shows its content (the map is loaded, the first image tracked...),
   * exceptionally if that failed. {@code jaria screenshot} waits for it.
   */
  CompletableFuture<Void> ready();

  /** Stops the app's threads and servers; the window may stay open. Idempotent. */
  @Override
  void close();
}
