package org.jaria.apps.monitor;

import java.util.List;
import java.util.Map;
import java.util.function.Predicate;
import org.jaria.apps.fx.PointLayer;
import org.jaria.map.ArMap;
import org.jaria.net.data.ConfigSection;
import org.jaria.net.data.InfoStrings;
import org.jaria.net.data.LocalizationSnapshot;
import org.jaria.net.data.NamedDrawing;
import org.jaria.net.data.Particles;
import org.jaria.net.data.PathSnapshot;
import org.jaria.net.data.PhysicalInfo;
import org.jaria.net.data.Points;
import org.jaria.net.data.PopupLayout;
import org.jaria.net.data.RobotUpdate;
import org.jaria.net.data.SensorReadings;
import org.jaria.net.data.VideoFrame;

/**
 * What the monitor knows about the robot: the latest value of everything it subscribed to. The
 * client's reader thread stores immutable records here; the JavaFX thread reads them when it draws.
 * Each field is replaced whole, never changed, so a reader sees one consistent value.
 */
final class MonitorState {

  /** The map and its points indexed for drawing. */
  record MapView(String name, long version, ArMap map, PointLayer points) {}

  volatile MapView map;
  volatile PhysicalInfo physical;
  volatile RobotUpdate robot;
  volatile SensorReadings sensors;
  volatile LocalizationSnapshot localization;
  volatile Particles particles;
  volatile PathSnapshot path;
  volatile InfoStrings strings;
  volatile List<ConfigSection> config;
  volatile VideoFrame video;
  volatile List<String> goals = List.of();

  /** The server's drawings (ArServerInfoDrawings), in its order, and each one's latest points. */
  volatile List<NamedDrawing> drawings = List.of();

  volatile Map<String, Points> drawingPoints = Map.of();

  /** The server's open popups by number (ArServerHandlerPopup). */
  volatile Map<Integer, PopupLayout.Shown> popups = Map.of();

  /**
   * Whether the first value of everything the window's status panel shows has arrived, of what the
   * server offers ({@code offered} says whether it offers a data name): the robot (pose, battery,
   * motors), the map, the localization and the information strings. {@code jaria screenshot} waits
   * for this, not just for the connection.
   */
  boolean firstDataArrived(Predicate<String> offered) {
    return (!offered.test("update") || robot != null)
        && (!(offered.test("getMap") || offered.test("getMapBinary")) || map != null)
        && (!(offered.test("getLocalizationSnapshot") || offered.test("getLocState"))
            || localization != null)
        && (!offered.test("getStrings") || strings != null);
  }

  /** Forgets everything (a new connection). */
  void clear() {
    map = null;
    physical = null;
    robot = null;
    sensors = null;
    localization = null;
    particles = null;
    path = null;
    strings = null;
    config = null;
    video = null;
    goals = List.of();
    drawings = List.of();
    drawingPoints = Map.of();
    popups = Map.of();
  }
}
