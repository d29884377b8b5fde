package org.jaria.net.server.info;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import java.util.function.Supplier;
import org.jaria.net.ArNetPacket;
import org.jaria.net.data.ArDrawingData;
import org.jaria.net.data.DrawingLayout;
import org.jaria.net.data.NamedDrawing;
import org.jaria.net.data.Points;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.Where;
import org.jaria.range.ArRangeDevice;

/**
 * Figures for clients to draw on the map (ArNetworking's {@code ArServerInfoDrawings}): {@code
 * "listDrawings"} and {@code "getDrawingList"} say what can be drawn and how ({@link
 * DrawingLayout}); each drawing is a data of its own name whose answer is the figure's points.
 * MobileEyes asks for the list, then for each drawing at its refresh time.
 *
 * <pre>{@code
 * ArServerInfoDrawings drawings = new ArServerInfoDrawings(server);
 * drawings.addRangeDevice(sonar);   // "sonarCurrent": blue arrows
 * drawings.addDrawing(ArDrawingData.of("polyLine", ArDrawingData.color(255, 0, 0), 2, 49),
 *     "route", () -> Points.of(route));
 * }</pre>
 *
 * <p>Drawings are listed in the order of their names ignoring case, as ArNetworking lists them. The
 * points are asked for on the server's worker threads: the suppliers must be thread-safe.
 */
public final class ArServerInfoDrawings {

  /** ArNetworking's drawing for a sonar's current readings. */
  public static final ArDrawingData SONAR_CURRENT =
      ArDrawingData.of("polyArrows", ArDrawingData.color(0x33, 0xCC, 0xFF), 200, 70);

  /** ArNetworking's drawing for a laser's current readings. */
  public static final ArDrawingData LASER_CURRENT =
      ArDrawingData.of("polyDots", ArDrawingData.color(0, 0, 255), 80, 75);

  /** ArNetworking's drawing for a laser's cumulative readings. */
  public static final ArDrawingData LASER_CUMULATIVE =
      ArDrawingData.of("polyDots", ArDrawingData.color(125, 125, 125), 100, 60);

  private static final String GROUP = "SensorInfo";

  private final ArServerBase server;

  // Written while the program sets up its drawings, read by the workers answering the lists.
  @GuardedBy("drawings")
  private final Map<String, ArDrawingData> drawings = new TreeMap<>(String.CASE_INSENSITIVE_ORDER);

  /** Registers {@code "listDrawings"} and {@code "getDrawingList"} with {@code server}. */
  public ArServerInfoDrawings(ArServerBase server) {
    this.server = Objects.requireNonNull(server, "server");
    server.addData(
        "listDrawings",
        "Deprecated; use getDrawingList instead. Gets a list of things that can be drawn",
        "none",
        "byte4: numDrawings, <repeats numDrawings> string: name, string: shape, byte4:"
            + " primaryColor(0RGB), byte4: size, byte4: layer, byte4: defaultRefreshTime(0 =="
            + " don't request refresh), byte4: secondaryColor(0RGB)",
        GROUP,
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> DrawingLayout.writeList(reply, getDrawings()));
    server.addData(
        "getDrawingList",
        "Gets a list of items to be drawn on the map. Each packet contains one drawing. "
            + " Terminates on empty packet.",
        "none",
        "For each drawing, a packet that contains: string: name, string: shape, byte4:"
            + " primaryColor(0RGB), byte4: size, byte4: layer, byte4: defaultRefreshTime(0 =="
            + " don't request refresh), byte4: secondaryColor(0RGB), string: visibility",
        GROUP,
        "RETURN_UNTIL_EMPTY",
        Where.WORKER,
        (client, request, reply) -> {
          int cmd = server.findCommandFromName("getDrawingList");
          for (NamedDrawing d : getDrawings()) {
            ArNetPacket p = new ArNetPacket(cmd);
            DrawingLayout.writeListed(p, d);
            client.sendPacketTcp(p);
          }
          // The (empty) reply the server sends next ends the list.
        });
  }

  /**
   * Adds a drawing: lists it, and registers data {@code name} answering {@code points} in
   * ArNetworking's layout (byte4 count, byte4 x, byte4 y per point).
   *
   * @return false if there already is a drawing or a data of that name (as ArNetworking)
   */
  public boolean addDrawing(ArDrawingData data, String name, Supplier<Points> points) {
    Objects.requireNonNull(data, "data");
    Objects.requireNonNull(points, "points");
    synchronized (drawings) {
      if (drawings.containsKey(name) || server.dataExists(name)) {
        return false;
      }
      server.addData(
          name,
          "",
          "none",
          "See getDrawingList for the information on how this drawing should be drawn, and the"
              + " documentation in ArDrawingData for that information means.",
          GROUP,
          "RETURN_SINGLE",
          Where.WORKER,
          (client, request, reply) -> DrawingLayout.writePoints(reply, points.get()));
      drawings.put(name, data);
      return true;
    }
  }

  /**
   * Adds a range device's current readings as drawing {@code <name>Current} (and, if {@code
   * cumulativeData} is not null, its cumulative readings as {@code <name>Cumulative}).
   *
   * @return whether every drawing was added
   */
  public boolean addRangeDevice(
      ArRangeDevice device, ArDrawingData currentData, ArDrawingData cumulativeData) {
    boolean ok =
        addDrawing(
            currentData,
            device.getName() + "Current",
            () -> Points.of(device.getCurrentReadings()));
    if (cumulativeData != null) {
      ok &=
          addDrawing(
              cumulativeData,
              device.getName() + "Cumulative",
              () -> Points.of(device.getCumulativeReadings()));
    }
    return ok;
  }

  /** Every drawing, in the order ArNetworking lists them. */
  public List<NamedDrawing> getDrawings() {
    synchronized (drawings) {
      List<NamedDrawing> l = new ArrayList<>(drawings.size());
      drawings.forEach((k, v) -> l.add(new NamedDrawing(k, v)));
      return l;
    }
  }
}
