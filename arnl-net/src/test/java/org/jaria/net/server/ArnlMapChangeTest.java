package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.map.ArMap;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.Futures;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.client.ArClientException;
import org.jaria.net.data.ConfigLayout;
import org.jaria.net.data.ConfigSection;
import org.jaria.net.protocol.NetError;
import org.junit.jupiter.api.Test;

/**
 * ARIA's {@code Files/Map} parameter with SonARNL behind the server: a client that sets it (as
 * {@code changeMapOnServer} does) changes the map the server navigates on and serves, and a name
 * that leads outside the map folder is refused. Hostile goal names are refused too.
 */
class ArnlMapChangeTest {

  @Test
  void settingFilesMapChangesTheMapForNavigationAndClients() throws Exception {
    try (ArnlRig rig = ArnlRig.arnl();
        ArClientBase watcher = new ArClientBase("watcher")) {
      watcher.connect("127.0.0.1", rig.gui.getServer().getPort(), "", "");
      AtomicInteger updated = new AtomicInteger();
      watcher.addHandler("mapUpdated", p -> updated.incrementAndGet());
      Futures.get(watcher.request("mapUpdated", -1));
      List<ConfigSection> sections = ConfigLayout.readAll(rig.call("getConfigBySections"));
      ConfigSection files = sections.get(0);
      assertEquals("Files", files.name(), "ARIA's section, first");
      assertEquals("Map", files.params().get(0).name());
      assertEquals("office.map", files.params().get(0).value());
      assertEquals("", rig.call("setConfig", "Section", "Files", "Map", "hall").bufToStr());
      assertEquals("hall", rig.call("getMapName").bufToStr());
      assertEquals(
          ArMap.loadBundled("hall").getLines().size(),
          rig.nav.getPathPlanningTask().getAriaMap().getLines().size(),
          "the planner plans on the new map");
      assertEquals(
          ArMap.loadBundled("hall").getGoals().stream().map(o -> o.name()).toList(),
          GuiRig.stringsToEnd(rig.call("getGoals")));
      Eventually.until("mapUpdated reached the other client", () -> updated.get() == 1);
      assertEquals("Stop", rig.gui.getModes().getMode(), "the robot was stopped first");
      ConfigSection after = ConfigLayout.readAll(rig.call("getConfigBySections")).get(0);
      assertEquals("hall", after.params().get(0).value());
    }
  }

  @Test
  void aClientAskingForAMapOutsideTheFolderIsAnsweredWithTheRefusal() throws Exception {
    try (ArnlRig rig = ArnlRig.arnl()) {
      ArNetPacket answer = rig.call("setConfig", "Section", "Files", "Map", "../../etc/passwd");
      String why = answer.bufToStr();
      assertTrue(why.startsWith("Map: "), why);
      assertEquals("office.map", rig.call("getMapName").bufToStr(), "the map stayed");
    }
  }

  @Test
  void aLongGoalNameIsRefusedAndUpdateStaysSmallForEveryClient() throws Exception {
    try (ArnlRig rig = ArnlRig.arnl();
        ArClientBase monitor = new ArClientBase("monitor")) {
      monitor.connect("127.0.0.1", rig.gui.getServer().getPort(), "", "");
      AtomicInteger updates = new AtomicInteger();
      AtomicInteger largest = new AtomicInteger();
      monitor.addHandler(
          "update",
          p -> {
            largest.accumulateAndGet(p.getDataLength(), Math::max);
            updates.incrementAndGet();
          });
      Futures.get(monitor.request("update", 20));
      for (int length : new int[] {31_000, 31_900}) {
        String name = "G".repeat(length);
        ArClientException e =
            assertThrows(ArClientException.class, () -> rig.call("gotoGoal", name));
        assertEquals(NetError.BAD_ARGUMENTS, e.getCode());
        assertTrue(e.getMessage().length() < 600, "the refusal is short too");
        int seen = updates.get();
        Eventually.until(
            "update is still published",
            () -> {
              rig.run(100);
              return updates.get() > seen + 1;
            });
      }
      assertTrue(largest.get() < 600, "update stayed small: " + largest.get() + " bytes");
    }
  }
}
