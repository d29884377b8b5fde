package org.jaria.net.client;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.net.Futures;
import org.jaria.net.PeerRecording;
import org.jaria.net.ReplayServer;
import org.jaria.net.data.ArDrawingData;
import org.jaria.net.data.DrawingLayout;
import org.jaria.net.data.NamedDrawing;
import org.jaria.net.data.Points;
import org.junit.jupiter.api.Test;

/**
 * Plays back what ARIA 2.9.1's drawingsExample (a server offering five drawings through {@code
 * ArServerInfoDrawings}) answered JAria's client, recorded by hand (see docs/networking.md), and
 * checks that the client reads its drawings as ArNetworking lays them out.
 */
class AriaDrawingsReplayTest {

  private static final List<String> NAMES =
      List.of(
          "exampleDrawing_Arrows",
          "exampleDrawing_circle",
          "exampleDrawing_Dots",
          "exampleDrawing_Home",
          "exampleDrawing_XMarksTheSpot");

  @Test
  void theClientReadsDrawingsExamplesDrawings() throws Exception {
    try (ReplayServer aria = new ReplayServer(PeerRecording.bytes("drawingsExample.s2c.bin"));
        ArClientBase c = new ArClientBase("monitor")) {
      c.connect("127.0.0.1", aria.port(), "", "");
      assertTrue(c.dataExists("listDrawings") && c.dataExists("getDrawingList"));
      List<NamedDrawing> listed =
          DrawingLayout.readList(Futures.get(c.requestOnce("listDrawings")));
      // ArNetworking lists them by name, ignoring case.
      assertEquals(NAMES, listed.stream().map(NamedDrawing::name).toList());
      List<NamedDrawing> all =
          DrawingLayout.readAllListed(Futures.get(c.requestOnce("getDrawingList")));
      assertEquals(NAMES, all.stream().map(NamedDrawing::name).toList());
      // drawingsExample's home: ArDrawingData("polyLine", ArColor(255, 0, 0), 2, 49).
      assertEquals(
          new ArDrawingData("polyLine", 0xFF0000, 2, 49, 200, 0, "DefaultOn"), all.get(3).data());
      assertEquals(
          new ArDrawingData("polyArrows", 0xFF00FF, 500, 100, 200, 0, "DefaultOn"),
          all.get(0).data());
      // Asked in the order they were recorded: each listed drawing once.
      assertEquals(
          1, DrawingLayout.readPoints(Futures.get(c.requestOnce("exampleDrawing_Arrows"))).size());
      Points circle = DrawingLayout.readPoints(Futures.get(c.requestOnce("exampleDrawing_circle")));
      assertEquals(360, circle.size(), "the circle of 360 points around (0, -5000)");
      assertEquals(-5000, circle.y(0));
      Points dots = DrawingLayout.readPoints(Futures.get(c.requestOnce("exampleDrawing_Dots")));
      assertEquals(List.of(3000, 3500, 4000), List.of(dots.x(0), dots.x(1), dots.x(2)));
      Points home = DrawingLayout.readPoints(Futures.get(c.requestOnce("exampleDrawing_Home")));
      assertEquals(7, home.size());
      assertEquals(List.of(-500, 500), List.of(home.x(0), home.y(0)));
      assertEquals(List.of(500, 500), List.of(home.x(6), home.y(6)));
      assertEquals(
          4,
          DrawingLayout.readPoints(Futures.get(c.requestOnce("exampleDrawing_XMarksTheSpot")))
              .size());
      c.disconnect();
      assertNull(aria.failure());
    }
  }
}
