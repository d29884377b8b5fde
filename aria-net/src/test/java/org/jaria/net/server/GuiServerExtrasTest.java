package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.net.Eventually;
import org.jaria.net.Futures;
import org.jaria.net.data.DrawingLayout;
import org.jaria.net.data.NamedDrawing;
import org.jaria.net.data.PopupInfo;
import org.jaria.net.data.PopupLayout;
import org.junit.jupiter.api.Test;

/** The guiServer's drawings, popups and configuration defaults, over the wire. */
class GuiServerExtrasTest {

  @Test
  void drawingsListTheSonarAndAnswerItsReadings() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      List<NamedDrawing> listed = DrawingLayout.readList(rig.call("listDrawings"));
      assertEquals(List.of("sonarCurrent"), listed.stream().map(NamedDrawing::name).toList());
      List<NamedDrawing> all = DrawingLayout.readAllListed(rig.call("getDrawingList"));
      assertEquals("polyArrows", all.get(0).data().shape());
      rig.run(500);
      int readings = rig.robot.findRangeDevice("sonar").getCurrentReadings().size();
      assertTrue(readings > 0);
      assertEquals(readings, DrawingLayout.readPoints(rig.call("sonarCurrent")).size(), 8);
    }
  }

  @Test
  void aPopupIsShownClickedAndClosedForEveryone() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      List<PopupLayout.Shown> shown = new CopyOnWriteArrayList<>();
      List<PopupLayout.Closed> closed = new CopyOnWriteArrayList<>();
      rig.client.addHandler(
          "popupCreate",
          p -> {
            PopupLayout.Shown s = PopupLayout.readCreate(p);
            if (s != null) {
              shown.add(s);
            }
          });
      rig.client.addHandler("popupClose", p -> closed.add(PopupLayout.readClose(p)));
      Futures.get(rig.client.request("popupCreate", -1));
      Futures.get(rig.client.request("popupClose", -1));
      // A round trip after the requests: the server has taken them when it answers.
      rig.call("popupList");
      AtomicInteger pressed = new AtomicInteger(99);
      PopupInfo ask =
          new PopupInfo(
              "",
              "Goal",
              "Go on?",
              PopupInfo.PopupType.QUESTION,
              0,
              1,
              0,
              "",
              "Yes",
              "Going on",
              "No",
              "Stopped",
              "",
              "");
      int id = rig.gui.getPopups().createPopup(ask, (popup, button) -> pressed.set(button));
      Eventually.until("the popup is shown", () -> shown.size() == 1);
      assertEquals("Go on?", shown.get(0).message());
      assertEquals(id, shown.get(0).id());
      // popupList sends the open popup again.
      rig.call("popupList");
      Eventually.until("listed again", () -> shown.size() == 2);
      rig.call("popupClicked", id, (byte) 1);
      Eventually.until("closed", () -> closed.size() == 1);
      assertEquals(new PopupLayout.Closed(id, "Stopped"), closed.get(0));
      assertEquals(1, pressed.get());
      assertTrue(rig.gui.getPopups().getOpenPopups().isEmpty());
      // A click on a popup no longer open changes nothing.
      rig.call("popupClicked", id, (byte) 0);
      assertEquals(1, pressed.get());
    }
  }

  @Test
  void aPopupTimesOutOnTheRobotsClock() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      List<PopupLayout.Closed> closed = new CopyOnWriteArrayList<>();
      rig.client.addHandler("popupClose", p -> closed.add(PopupLayout.readClose(p)));
      Futures.get(rig.client.request("popupClose", -1));
      rig.call("popupList");
      AtomicInteger pressed = new AtomicInteger(99);
      PopupInfo soon =
          new PopupInfo(
              "",
              "Battery",
              "Low",
              PopupInfo.PopupType.WARNING,
              0,
              0,
              2,
              "Nobody answered",
              "OK",
              "",
              "",
              "",
              "",
              "");
      int id = rig.gui.getPopups().createPopup(soon, (popup, button) -> pressed.set(button));
      rig.run(1000);
      assertEquals(99, pressed.get(), "not yet");
      rig.run(1500);
      assertEquals(-1, pressed.get(), "timed out");
      Eventually.until("closed", () -> closed.size() == 1);
      assertEquals(new PopupLayout.Closed(id, "Nobody answered"), closed.get(0));
    }
  }

  @Test
  void homeDrivesToTheMapsHomeAndDockIsRefusedSayingWhy() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      rig.call("gotoPose", 4000, 9500);
      rig.run(3000);
      rig.call("home");
      rig.run(200);
      assertEquals(
          "Goto", org.jaria.net.server.modes.ArServerModes.of(rig.gui.getServer()).getMode());
      assertTrue(
          rig.runUntil(
              () ->
                  rig.sim.sim().getTruePose().findDistanceTo(new org.jaria.geom.ArPose(1500, 9500))
                      < 300,
              60_000),
          "back home: " + rig.sim.sim().getTruePose());
      var refused = Futures.failure(rig.client.requestOnce("dock"));
      assertTrue(refused.getMessage().contains("(29300, 9500)"), refused.getMessage());
    }
  }

  @Test
  void getMapBinaryGivesTheSameMap() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      String text = org.jaria.net.data.MapBinaryLayout.readText(rig.call("getMapBinary"));
      org.jaria.map.ArMap back =
          org.jaria.map.ArMap.read(new java.io.StringReader(text), "getMapBinary");
      assertEquals(GuiRig.OFFICE.getLines(), back.getLines());
      assertEquals(GuiRig.OFFICE.getPoints(), back.getPoints());
      assertEquals(GuiRig.OFFICE.getMapObjects(), back.getMapObjects());
    }
  }
}
