package org.jaria.apps.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.action.ArActionGroup;
import org.jaria.geom.ArPose;
import org.jaria.net.data.ArDrawingData;
import org.jaria.net.data.LocalizationSnapshot;
import org.jaria.net.data.Particles;
import org.jaria.net.data.PathSnapshot;
import org.jaria.net.data.Points;
import org.jaria.net.data.PopupInfo;
import org.jaria.net.provider.LocalizationInfo;
import org.jaria.net.provider.PathPlanningInfo;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.ServerOptions;
import org.jaria.net.server.info.ArServerHandlerPopup;
import org.jaria.net.server.info.ArServerInfoDrawings;
import org.jaria.net.server.info.ArServerInfoLocalization;
import org.jaria.net.server.info.ArServerInfoPath;
import org.junit.jupiter.api.Test;

/**
 * The monitor's link against a server laid out as ARNL's (no JAria snapshots): it reads {@code
 * getLocState} and {@code getPath} in ARNL's layouts, fetches the drawings and their points, and
 * keeps the server's open popups, closing them when the server does.
 */
class GuiServerLinkTest {

  private static final Points PATH = Points.ofFlat(new int[] {0, 0, 1000, 500, 2000, 500}, 2);

  private static final LocalizationInfo LOC =
      new LocalizationInfo() {
        @Override
        public LocalizationSnapshot getLocalizationState() {
          return new LocalizationSnapshot(
              "LOCALIZATION_SUCCESS", 0.81, new ArPose(1, 2), 500, false);
        }

        @Override
        public Particles getParticles() {
          return Particles.NONE;
        }

        @Override
        public boolean localizeToPose(ArPose pose) {
          return false;
        }
      };

  private static final PathPlanningInfo PLANNER =
      new PathPlanningInfo() {
        @Override
        public PathSnapshot getPathState() {
          return new PathSnapshot("MOVING_TO_GOAL", "", new ArPose(2000, 500), PATH, Points.EMPTY);
        }

        @Override
        public String getStatusString() {
          return "";
        }

        @Override
        public boolean pathPlanToPose(ArPose goal, boolean useHeading) {
          return false;
        }

        @Override
        public boolean pathPlanToGoal(String goalName) {
          return false;
        }

        @Override
        public void cancelPathPlan() {}

        @Override
        public ArActionGroup getActionGroup() {
          return null;
        }
      };

  private static void until(String what, java.util.function.BooleanSupplier c) {
    long end = System.nanoTime() + Duration.ofSeconds(20).toNanos();
    while (!c.getAsBoolean()) {
      if (System.nanoTime() > end) {
        throw new AssertionError("not within 20 s: " + what);
      }
      java.util.concurrent.locks.LockSupport.parkNanos(200_000);
    }
  }

  @Test
  void arnlLayoutsDrawingsAndPopups() throws Exception {
    try (ArServerBase server = new ArServerBase(ServerOptions.builder().port(0).build())) {
      new ArServerInfoLocalization(server, LOC);
      new ArServerInfoPath(server, PLANNER);
      ArServerInfoDrawings drawings = new ArServerInfoDrawings(server);
      drawings.addDrawing(
          ArDrawingData.of("polyDots", ArDrawingData.color(0, 255, 0), 250, 48),
          "dots",
          () -> Points.ofFlat(new int[] {3000, 0, 3500, 100}, 2));
      ArServerHandlerPopup popups = new ArServerHandlerPopup(server, () -> 0L);
      server.open();
      MonitorState state = new MonitorState();
      AtomicInteger changes = new AtomicInteger();
      try (GuiServerLink link = new GuiServerLink(state, changes::incrementAndGet)) {
        link.connect("127.0.0.1", server.getPort(), "", null);
        until("ARNL's getLocState", () -> state.localization != null);
        assertEquals("LOCALIZATION_SUCCESS", state.localization.state());
        assertEquals(0.81, state.localization.score(), 1e-9);
        assertNull(state.localization.pose(), "ARNL's layout has no pose");
        until("ARNL's getPath", () -> state.path != null);
        assertEquals(PATH, state.path.path());
        until("the drawing's points", () -> state.drawingPoints.containsKey("dots"));
        assertEquals(List.of("dots"), state.drawings.stream().map(d -> d.name()).toList());
        assertEquals(2, state.drawingPoints.get("dots").size());
        int id =
            popups.createPopup(
                PopupInfo.message("Battery", "Low", PopupInfo.PopupType.WARNING), null);
        until("the popup", () -> state.popups.containsKey(id));
        assertEquals("Low", state.popups.get(id).message());
        popups.closePopup(id, "Charged");
        until("the popup closed", () -> state.popups.isEmpty());
        assertTrue(changes.get() > 0);
      }
    }
  }
}
