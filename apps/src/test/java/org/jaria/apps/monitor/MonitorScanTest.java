package org.jaria.apps.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import javafx.stage.Stage;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.FxRuntime;
import org.jaria.apps.fx.Mouse;
import org.jaria.apps.fx.ScriptedPrompts;
import org.jaria.map.ArMap;
import org.jaria.net.arnl.ArnlNavigation;
import org.jaria.net.data.Points;
import org.jaria.net.server.MapFolder;
import org.jaria.net.server.ServerOptions;
import org.jaria.simguiserver.ScanMapping;
import org.jaria.simguiserver.SimulatedGuiServer;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.testfx.api.FxRobot;
import org.testfx.framework.junit5.ApplicationExtension;
import org.testfx.framework.junit5.Start;
import org.testfx.util.WaitForAsyncUtils;

/**
 * Mapping from the monitor: on a guiServer with mapping, Scan… starts a scan, the robot wanders,
 * the monitor draws the map as it grows (the server's drawing), End scan ends it and the map is
 * built in the server's folder; a refused name is said in a dialog.
 */
@Tag("gui")
@ExtendWith(ApplicationExtension.class)
class MonitorScanTest {

  @TempDir Path dir;

  private final ScriptedPrompts prompts = new ScriptedPrompts();
  private Stage stage;

  @Start
  void start(Stage s) {
    stage = s;
  }

  private static void waitFor(String what, Callable<Boolean> condition) {
    try {
      WaitForAsyncUtils.waitFor(60, TimeUnit.SECONDS, condition);
    } catch (java.util.concurrent.TimeoutException e) {
      throw new AssertionError("not within 60 s: " + what, e);
    }
  }

  private static int drawn(MonitorWindow w) {
    Points p = w.state().drawingPoints.get(ScanMapping.DRAWING);
    return p == null ? 0 : p.size();
  }

  @Test
  void scanFromTheMonitorAndWatchTheMapGrow(FxRobot robot) throws Exception {
    List<String> said = new CopyOnWriteArrayList<>();
    try (SimulatedGuiServer server =
            SimulatedGuiServer.start(
                new SimulatedGuiServer.Options(
                    ArMap.loadBundled("hall"),
                    "hall.map",
                    "p3dx-sh",
                    1,
                    // The default limit of waiting requests: the monitor's connection
                    // (some 25 requests at once) must not be refused part of them.
                    ServerOptions.builder().port(0).bindAddress("127.0.0.1").build(),
                    ArnlNavigation.Mode.THREADED,
                    8.0,
                    false),
                new MapFolder(dir));
        ScanMapping mapping =
            ScanMapping.withSimulatedLaser(server.gui(), server.robot(), dir, said::add)) {
      MonitorWindow w =
          FxRuntime.call(
              () -> {
                MonitorWindow m =
                    new MonitorWindow(
                        stage,
                        AppEnvironment.scripted(prompts),
                        "127.0.0.1",
                        server.port(),
                        "",
                        null);
                stage.setWidth(1280);
                stage.setHeight(750);
                m.show();
                return m;
              },
              10);
      try {
        w.ready().get(30, TimeUnit.SECONDS);
        Mouse mouse = new Mouse(robot);
        prompts.texts.add("../outside");
        mouse.click("#scan-start");
        waitFor("the refusal is said", () -> !prompts.errors.isEmpty());
        assertTrue(prompts.errors.get(0).contains("without folders"), prompts.errors::toString);

        prompts.texts.add("Hall2");
        mouse.click("#scan-start");
        waitFor(
            "scanning",
            () -> FxRuntime.call(() -> w.scanControls().status(), 10).startsWith("Scanning"));
        mouse.click("#wander");
        waitFor("the monitor draws the map growing", () -> drawn(w) > 100);
        mouse.click("#scan-end");
        waitFor("the map is built", () -> mapping.mapsBuilt() == 1);
        assertTrue(Files.isRegularFile(dir.resolve("hall2.2d")));
        assertTrue(Files.isRegularFile(dir.resolve("hall2.map")));
        assertEquals(1, prompts.errors.size(), prompts.errors::toString);
      } finally {
        FxRuntime.run(
            () -> {
              w.stage().hide();
              w.close();
            },
            10);
      }
    }
  }
}
