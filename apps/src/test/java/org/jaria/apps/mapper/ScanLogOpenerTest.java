package org.jaria.apps.mapper;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import javafx.scene.image.PixelReader;
import javafx.scene.image.WritableImage;
import javafx.stage.Stage;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.FxRuntime;
import org.jaria.apps.fx.ScriptedPrompts;
import org.jaria.map.ArMap;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.testfx.framework.junit5.ApplicationExtension;
import org.testfx.framework.junit5.Start;
import org.testfx.util.WaitForAsyncUtils;

/**
 * The map editor opens a scan log: it builds the map on its worker, shows the log's readings under
 * it, and the map is then edited and saved as any other; a broken log is a clear error.
 */
@Tag("gui")
@ExtendWith(ApplicationExtension.class)
class ScanLogOpenerTest {

  @TempDir Path dir;

  private final ScriptedPrompts prompts = new ScriptedPrompts();
  private MapperWindow window;

  @Start
  void start(Stage stage) {
    window = new MapperWindow(stage, AppEnvironment.scripted(prompts));
  }

  @AfterEach
  void closeWindow() {
    FxRuntime.run(() -> window.stage().hide(), 10);
    window.close();
  }

  /** A scan log of the hall, as {@code jaria laser log --sim hall --seconds 90} writes it. */
  private Path log() throws Exception {
    Path log = dir.resolve("hall.2d");
    int scans = SimulatedScanLog.record("hall", 90, log);
    assertTrue(scans > 0, "scans logged: " + scans);
    return log;
  }

  /** Pixels of the map view with the underlay's colour. */
  private int underlayPixels() {
    WritableImage img =
        FxRuntime.call(
            () -> {
              window.view().paint();
              return window.view().snapshot(null, null);
            },
            10);
    PixelReader r = img.getPixelReader();
    int n = 0;
    for (int y = 0; y < (int) img.getHeight(); y++) {
      for (int x = 0; x < (int) img.getWidth(); x++) {
        if ((r.getArgb(x, y) | 0xFF000000) == MapRenderer.UNDERLAY_ARGB) {
          n++;
        }
      }
    }
    return n;
  }

  @Test
  void aScanLogIsBuiltShownOverItsReadingsAndSavedAsAMap() throws Exception {
    Path log = log();
    FxRuntime.run(() -> window.show(log), 10);
    window.ready().get(60, TimeUnit.SECONDS);
    WaitForAsyncUtils.waitForFxEvents();
    assertTrue(prompts.errors.isEmpty(), prompts.errors::toString);
    int points = window.document().content().points().size();
    assertTrue(points > 200, "points: " + points);
    assertEquals("hall.map", window.document().title());
    assertTrue(underlayPixels() > 100, "the log's readings are drawn under the map");

    Path saved = dir.resolve("mine.map");
    assertTrue(FxRuntime.call(() -> window.saveTo(saved), 10));
    assertTrue(window.work().awaitIdle(30, TimeUnit.SECONDS));
    assertEquals(points, ArMap.readFile(saved).getPoints().size());

    FxRuntime.run(() -> window.open(saved), 10);
    assertTrue(window.work().awaitIdle(30, TimeUnit.SECONDS));
    WaitForAsyncUtils.waitForFxEvents();
    assertEquals(0, underlayPixels(), "an ordinary map has no readings under it");
  }

  @Test
  void aBrokenLogIsAClearError() throws Exception {
    Path log = dir.resolve("broken.2d");
    Files.writeString(log, "LaserOdometryLog\nsick1pose: 0 0 0\nrobot: abc\n");
    FxRuntime.run(() -> window.show(log), 10);
    ExecutionException e =
        assertThrows(ExecutionException.class, () -> window.ready().get(30, TimeUnit.SECONDS));
    assertTrue(e.getCause().getMessage() != null);
    WaitForAsyncUtils.waitForFxEvents();
    assertEquals(1, prompts.errors.size(), prompts.errors::toString);
    assertTrue(prompts.errors.get(0).startsWith("Cannot build a map from broken.2d"));
  }
}
