package org.jaria.apps.fx;

import java.io.PrintWriter;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import javafx.application.Platform;
import javafx.stage.Stage;
import javafx.stage.WindowEvent;

/** Runs a desktop app from the command line until the user closes its window. */
public final class AppLauncher {

  private AppLauncher() {}

  /**
   * Starts JavaFX, opens the app with the user's settings and real dialogs, waits until its main
   * window is closed, then releases the app and stops JavaFX.
   *
   * @return the command's exit status: 0, or 1 if the app could not start (reported on {@code err})
   */
  public static int runUntilClosed(AppCommand command, PrintWriter err) {
    Optional<String> problem = GuiCheck.problem();
    if (problem.isPresent()) {
      err.println("jaria " + command.appName() + ": " + problem.get());
      err.flush();
      return 1;
    }
    try {
      FxRuntime.startup();
    } catch (IllegalStateException e) {
      err.println("jaria " + command.appName() + ": " + e.getMessage());
      err.flush();
      return 1;
    }
    CountDownLatch closed = new CountDownLatch(1);
    DesktopApp app;
    try {
      app =
          FxRuntime.call(
              () -> {
                Stage stage = new Stage();
                stage.addEventHandler(WindowEvent.WINDOW_HIDDEN, e -> closed.countDown());
                return command.open(stage, AppEnvironment.forUser(command.appName()));
              },
              120);
    } catch (RuntimeException e) {
      err.println("jaria " + command.appName() + ": " + e.getMessage());
      err.flush();
      Platform.exit();
      return 1;
    }
    try {
      closed.await();
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } finally {
      app.close();
      Platform.exit();
    }
    return 0;
  }
}
