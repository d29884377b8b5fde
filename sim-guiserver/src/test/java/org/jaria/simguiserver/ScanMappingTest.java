package org.jaria.simguiserver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.jaria.laser.log.LoggedScan;
import org.jaria.laser.log.ScanLogReader;
import org.jaria.map.ArMap;
import org.jaria.net.ArNetPacket;
import org.jaria.net.arnl.ArnlNavigation;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.data.DrawingLayout;
import org.jaria.net.data.LiveMap;
import org.jaria.net.data.Points;
import org.jaria.net.server.MapFolder;
import org.jaria.net.server.ServerOptions;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Mapping while driving over a real socket: a client (aria-net's {@link ArClientBase}) starts a
 * scan on the simulated guiServer, the robot wanders, the monitor-side subscription sees the map
 * grow, the client ends the scan, and the log and the map built from it are in the map folder,
 * where a client can switch to the map.
 */
@Tag("slow")
class ScanMappingTest {

  @Test
  void startDriveEndBuildsTheMapInTheFolder(@TempDir Path dir) throws Exception {
    List<String> said = new CopyOnWriteArrayList<>();
    try (SimulatedGuiServer s =
            SimulatedGuiServer.start(
                new SimulatedGuiServer.Options(
                    ArMap.loadBundled("hall"),
                    "hall.map",
                    "p3dx-sh",
                    2,
                    ServerOptions.builder().port(0).bindAddress("127.0.0.1").build(),
                    ArnlNavigation.Mode.SYNCHRONOUS,
                    0,
                    false),
                new MapFolder(dir));
        ScanMapping mapping = ScanMapping.withSimulatedLaser(s.gui(), s.robot(), dir, said::add);
        ArClientBase client = new ArClientBase("mapper")) {
      s.sim().runMillis(500);
      client.connect("127.0.0.1", s.port(), "", "");
      List<LiveMap> live = new CopyOnWriteArrayList<>();
      client.addHandler("mappingLiveMap", p -> live.add(LiveMap.read(p)));

      assertEquals(0, await(s, client.requestOnce("mappingStart", "Hall1")).bufToByte());
      await(s, client.request("mappingLiveMap", 100));
      await(s, client.requestOnce("wander"));
      for (int i = 0; i < 90; i++) {
        s.sim().runMillis(1000);
      }
      ArNetPacket end = await(s, client.requestOnce("mappingEnd"));
      assertEquals(0, end.bufToUByte2(), "ended");
      long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
      while (mapping.mapsBuilt() == 0 && System.nanoTime() < deadline) {
        s.sim()
            .runMillis(100); // the builder's thread works meanwhile; the world is only kept alive
      }
      assertEquals(1, mapping.mapsBuilt(), "built: " + said);
      Path log = dir.resolve("hall1.2d");
      long scans;
      try (ScanLogReader r = ScanLogReader.open(log)) {
        scans = r.readAll().stream().filter(e -> e instanceof LoggedScan).count();
      }
      assertTrue(scans >= 20, "scans logged: " + scans);
      Path map = dir.resolve("hall1.map");
      assertEquals(map, mapping.lastMap());
      ArMap built = ArMap.readFile(map);
      assertTrue(built.getPoints().size() > 200, "points: " + built.getPoints().size());
      assertTrue(
          live.stream().anyMatch(m -> m.points().size() > 50 && m.fileName().equals("hall1.2d")),
          "the map was seen growing");
      assertTrue(said.stream().anyMatch(x -> x.startsWith("built hall1.map")), said.toString());
      assertEquals(0, mapping.dropped());
      Points drawn = DrawingLayout.readPoints(await(s, client.requestOnce(ScanMapping.DRAWING)));
      assertTrue(drawn.size() > 200, "the built map stays drawn for monitors: " + drawn.size());
      assertTrue(
          DrawingLayout.readList(await(s, client.requestOnce("listDrawings"))).stream()
              .anyMatch(d -> d.name().equals(ScanMapping.DRAWING)),
          "listed as a drawing");
      // A second scan of the same name never replaces the first map.
      assertEquals(0, await(s, client.requestOnce("mappingStart", "hall1")).bufToByte());
      for (int i = 0; i < 30; i++) {
        s.sim().runMillis(1000);
      }
      assertEquals(0, await(s, client.requestOnce("mappingEnd")).bufToUByte2());
      deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
      while (mapping.mapsBuilt() == 1 && System.nanoTime() < deadline) {
        s.sim().runMillis(100);
      }
      assertEquals(dir.resolve("hall1-2.map"), mapping.lastMap());
      assertTrue(Files.isRegularFile(map));
    }
  }

  /** The future's value, advancing the world while the server waits for the robot's cycle. */
  private static <T> T await(SimulatedGuiServer s, CompletableFuture<T> f) throws Exception {
    long end = System.nanoTime() + Duration.ofSeconds(30).toNanos();
    while (true) {
      if (s.gui().getServer().getPendingCycleCommands() > 0) {
        s.world().step();
      }
      try {
        return f.get(1, TimeUnit.MILLISECONDS);
      } catch (TimeoutException e) {
        if (System.nanoTime() > end) {
          throw new AssertionError("no reply within 30 s", e);
        }
      }
    }
  }
}
