package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.net.Eventually;
import org.jaria.net.Futures;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.data.ConfigDefaultsLayout;
import org.jaria.net.data.DrawingLayout;
import org.jaria.net.data.NamedDrawing;
import org.junit.jupiter.api.Test;

/** The guiServer's drawings, configuration and requests with SonARNL's services behind them. */
class GuiServerArnlExtrasTest {

  @Test
  void thePlannedPathIsADrawing() throws Exception {
    try (ArnlRig rig = ArnlRig.arnl()) {
      List<String> names =
          DrawingLayout.readAllListed(rig.call("getDrawingList")).stream()
              .map(NamedDrawing::name)
              .toList();
      assertTrue(names.contains("pathPlannerPath"), names.toString());
      assertEquals(0, DrawingLayout.readPoints(rig.call("pathPlannerPath")).size(), "no goal yet");
    }
  }

  @Test
  void configDefaultsAndConfigUpdatedForTheOtherClients() throws Exception {
    try (ArnlRig rig = ArnlRig.arnl();
        ArClientBase other = new ArClientBase("other")) {
      other.connect("127.0.0.1", rig.gui.getServer().getPort(), "", "");
      AtomicInteger updatesOther = new AtomicInteger();
      AtomicInteger updatesSetter = new AtomicInteger();
      other.addHandler("configUpdated", p -> updatesOther.incrementAndGet());
      rig.client.addHandler("configUpdated", p -> updatesSetter.incrementAndGet());
      Futures.get(other.request("configUpdated", -1));
      Futures.get(rig.client.request("configUpdated", -1));
      // Round trips after the requests: the server has taken them when it answers.
      Futures.get(other.requestOnce("getConfigDefaults"));
      var defaults = ConfigDefaultsLayout.read(rig.call("getConfigDefaults"));
      assertTrue(defaults.containsKey("Localization"), defaults.keySet().toString());
      String numSamples = defaults.get("Localization").get("NumSamples");
      var one = ConfigDefaultsLayout.read(rig.call("getConfigDefaults", "localization"));
      assertEquals(List.of("Localization"), List.copyOf(one.keySet()));
      assertEquals(
          "", rig.call("setConfig", "Section", "Localization", "NumSamples", "700").bufToStr());
      Eventually.until("the other client hears configUpdated", () -> updatesOther.get() == 1);
      // The defaults stay the defaults.
      assertEquals(
          numSamples,
          ConfigDefaultsLayout.read(rig.call("getConfigDefaults"))
              .get("Localization")
              .get("NumSamples"));
      assertEquals(0, updatesSetter.get(), "the client that set it is not told");
    }
  }

  @Test
  void hostileArgumentsAreRefusedOneRequestAtATime() throws Exception {
    try (ArnlRig rig = ArnlRig.arnl()) {
      // popupClicked cut short (a byte where a byte4 belongs), and with text for numbers.
      assertEquals(
          org.jaria.net.protocol.NetError.BAD_ARGUMENTS,
          Futures.failure(rig.client.requestOnce("popupClicked", (byte) 1)).getCode());
      assertEquals(
          org.jaria.net.protocol.NetError.BAD_ARGUMENTS,
          Futures.failure(rig.client.requestOnce("popupClicked", "ab")).getCode());
      // Text long enough to read as numbers reads as a popup number nobody has: ignored.
      rig.call("popupClicked", "seven");
      // getConfigDefaults with a section name without its ending zero byte.
      assertEquals(
          org.jaria.net.protocol.NetError.BAD_ARGUMENTS,
          Futures.failure(rig.client.requestOnce("getConfigDefaults", new byte[] {'L', 'o'}))
              .getCode());
      // An oversized section name (near the packet's limit) names no section: nothing is sent.
      String huge = "x".repeat(31_000);
      assertEquals(0, rig.call("getConfigDefaults", huge).getDataLength());
      // Arguments nobody asked for are ignored, as ArNetworking ignores them.
      assertTrue(DrawingLayout.readList(rig.call("listDrawings", 1, 2, 3)).size() > 0);
      // The connection and the server carry on.
      assertTrue(ConfigDefaultsLayout.read(rig.call("getConfigDefaults")).size() > 0);
      assertTrue(rig.client.isConnected());
    }
  }
}
