package org.jaria.net.guiserver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.Futures;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.client.ArClientException;
import org.jaria.net.protocol.NetError;
import org.jaria.net.server.TextLimits;
import org.jaria.net.server.modes.ArServerMode;
import org.junit.jupiter.api.Test;

/**
 * The guiServer's answers to a user whose long strings would break {@code update} for everybody: a
 * goal name too long for the update packet, and a mode that writes a huge status line (the
 * server-side limits are tested in {@code org.jaria.net.server.HostileClientsTest}).
 */
class GuiServerLongStringsTest {

  @Test
  void aLongGoalNameIsRefusedAndUpdateStaysSmallForEveryClient() throws Exception {
    try (GuiRig rig = GuiRig.arnl();
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


  @Test
  void aStatusLineIsCutWhateverAModeWritesInIt() throws Exception {
    try (GuiRig rig = GuiRig.plain(b -> b)) {
      var chatty =
          new ArServerMode(rig.gui.getServer(), rig.robot, "Chatty") {
            @Override
            protected void onActivate() {
              setStatus("x".repeat(40_000));
            }

            @Override
            protected void onDeactivate() {}
          };
      assertTrue(rig.gui.getServer().runOnCycle(chatty::activate));
      rig.run(300);
      assertEquals(TextLimits.MAX_MESSAGE, chatty.getStatus().length());
      ArNetPacket update = rig.call("update");
      assertTrue(update.getDataLength() < 700, "update: " + update.getDataLength() + " bytes");
    }
  }
}
