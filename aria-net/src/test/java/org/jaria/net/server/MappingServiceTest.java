package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.stream.Stream;
import org.jaria.laser.log.LoggedScan;
import org.jaria.laser.log.ScanLogEntry;
import org.jaria.laser.log.ScanLogReader;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.Futures;
import org.jaria.net.RawClient;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.data.LiveMap;
import org.jaria.net.protocol.Protocol;
import org.jaria.net.server.info.ArServerHandlerMapping;
import org.jaria.range.ArSimulatedLaser;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * ArNetworking's mapping services (ARIA 2.9.1's {@code ArServerHandlerMapping}): a client starts a
 * scan with a file name, the robot drives, the client ends it, and the log is in the map folder;
 * names outside the folder and users without the Mapping group are refused, and the server keeps
 * serving.
 */
class MappingServiceTest {

  /** A guiServer on the simulated office with a laser and the mapping services on {@code dir}. */
  private static final class Rig implements AutoCloseable {
    final GuiRig rig;
    final ArServerHandlerMapping mapping;

    Rig(Path dir, ServerOptions options, String user, String password) throws Exception {
      ArServerHandlerMapping[] made = new ArServerHandlerMapping[1];
      rig =
          GuiRig.plain(
              b -> options == null ? b : b.options(options),
              g -> made[0] = install(g, dir),
              user,
              password);
      mapping = made[0];
      rig.run(500);
    }

    Rig(Path dir) throws Exception {
      this(dir, null, "", "");
    }

    private static ArServerHandlerMapping install(GuiRig g, Path dir) {
      ArSimulatedLaser laser = new ArSimulatedLaser();
      g.robot.lock();
      try {
        g.robot.addRangeDevice(laser);
      } finally {
        g.robot.unlock();
      }
      try {
        ArServerHandlerMapping m =
            new ArServerHandlerMapping(g.gui.getServer(), g.robot, laser, dir);
        m.addLiveMap();
        return m;
      } catch (java.io.IOException e) {
        throw new java.io.UncheckedIOException(e);
      }
    }

    /** Wanders (the guiServer's wander mode) for {@code ms} of virtual time. */
    void drive(long ms) throws Exception {
      rig.robot.lock();
      try {
        rig.robot.enableMotors();
      } finally {
        rig.robot.unlock();
      }
      rig.call("wander");
      rig.run(ms);
    }

    @Override
    public void close() {
      mapping.close();
      rig.close();
    }
  }

  @Test
  void aClientStartsDrivesAndEndsAScan(@TempDir Path dir) throws Exception {
    try (Rig r = new Rig(dir);
        ArClientBase watcher = new ArClientBase("watcher")) {
      watcher.connect("127.0.0.1", r.rig.gui.getServer().getPort(), "", "");
      List<String> broadcasts = new CopyOnWriteArrayList<>();
      watcher.addHandler("mappingStatusBroadcast", p -> broadcasts.add(p.bufToStr()));
      Futures.get(watcher.request("mappingStatusBroadcast", -1));
      Eventually.until("the first answer", () -> broadcasts.size() == 1);
      List<ScanLogEntry> live = new CopyOnWriteArrayList<>();
      r.mapping.addLogEntryCallback((h, e) -> live.add(e));

      assertEquals("", r.rig.call("mappingStatus").bufToStr());
      assertEquals(0, r.rig.call("mappingStart", "Lab").bufToByte(), "started");
      assertEquals("lab", r.rig.call("mappingStatus").bufToStr(), "ARIA lower-cases the name");
      assertEquals(1, r.rig.call("mappingStart", "other").bufToByte(), "one scan at a time");
      r.drive(20_000);
      r.mapping.publishLiveMap(
          LiveMap.of("scanning", "lab.2d", 3, new int[] {1, 2}, new int[0], null));
      LiveMap m = LiveMap.read(r.rig.call("mappingLiveMap"));
      assertEquals("lab.2d", m.fileName());
      ArNetPacket ended = r.rig.call("mappingEnd");
      assertEquals(2, ended.getDataLength(), "ArNetworking's ubyte2 for an ended scan");
      assertEquals(0, ended.bufToUByte2());
      assertEquals(1, r.rig.call("mappingEnd").bufToByte(), "no scan to end");
      assertEquals("", r.rig.call("mappingStatus").bufToStr());
      Eventually.until("start and end broadcast", () -> broadcasts.size() == 3);
      assertEquals(List.of("", "lab.2d", ""), broadcasts);

      Path log = dir.resolve("lab.2d");
      assertTrue(Files.isRegularFile(log));
      try (ScanLogReader reader = ScanLogReader.open(log)) {
        List<ScanLogEntry> all = reader.readAll();
        long scans = all.stream().filter(e -> e instanceof LoggedScan).count();
        assertTrue(scans >= 10, "a scan every 300 mm of a 5 m drive: " + scans);
        assertEquals(all.size(), live.size(), "every entry reached the callback");
      }
      assertEquals(List.of(log), listing(dir), "nothing else was written");
    }
  }

  @Test
  void namesOutsideTheFolderAreRefusedAndTheServerKeepsServing(@TempDir Path tmp) throws Exception {
    Path dir = Files.createDirectories(tmp.resolve("maps"));
    Files.writeString(tmp.resolve("secret.2d"), "keep");
    Files.createSymbolicLink(dir.resolve("link.2d"), tmp.resolve("secret.2d"));
    Files.createSymbolicLink(dir.resolve("null.2d"), Path.of("/dev/null"));
    Files.createDirectories(dir.resolve("folder.2d"));
    try (Rig r = new Rig(dir)) {
      String[][] refused = {
        {"../secret", "without folders"},
        {"..", "does not start with a dot"},
        {tmp.resolve("secret").toString(), "without folders"},
        {"sub/x", "without folders"},
        {"c:x", "without folders"},
        {"link", "is a link"},
        {"null.2d", "is a link"},
        {"folder", "is not a file"},
        {"", "give the scan a file name"},
        {"a\u0001b", "no control characters"},
        {"x".repeat(300), "at most 256 characters"},
        {" lab", "spaces"},
      };
      for (String[] bad : refused) {
        ArNetPacket p = r.rig.call("mappingStart", bad[0]);
        assertEquals(2, p.bufToByte(), bad[0]);
        String why = p.bufToStr();
        assertTrue(why.contains(bad[1]), bad[0] + ": " + why);
        assertEquals("", r.rig.call("mappingStatus").bufToStr(), "nothing started");
      }
      ArNetPacket none = new ArNetPacket(r.rig.gui.getServer().findCommandFromName("mappingStart"));
      assertEquals(2, r.rig.await(r.rig.client.requestOnce("mappingStart", none)).bufToByte());
      assertEquals("keep", Files.readString(tmp.resolve("secret.2d")), "not written through");
      assertEquals(0, r.rig.call("mappingStart", "ok").bufToByte(), "the server still serves");
      assertEquals(0, r.rig.call("mappingEnd").bufToUByte2());
      assertTrue(Files.isRegularFile(dir.resolve("ok.2d")));
    }
  }

  @Test
  void aUserWithoutTheMappingGroupIsRefused(@TempDir Path dir) throws Exception {
    Authenticator users =
        ArServerUserInfo.parse(
            List.of(
                "UserInfoVersion1",
                ArServerUserInfo.makeLine("mapper", "pw") + " Mapping RobotInfo",
                ArServerUserInfo.makeLine("visitor", "look") + " RobotInfo"),
            "users");
    ServerOptions o = ServerOptions.builder().port(0).authenticator(users).build();
    try (Rig r = new Rig(dir, o, "mapper", "pw");
        ArClientBase visitor = new ArClientBase("visitor");
        ArClientBase mapper = new ArClientBase("mapper");
        RawClient raw = new RawClient(r.rig.gui.getServer().getPort())) {
      int port = r.rig.gui.getServer().getPort();
      visitor.connect("127.0.0.1", port, "visitor", "look");
      assertFalse(visitor.dataExists("mappingStart"), "not listed for a RobotInfo user");
      assertTrue(visitor.dataExists("mappingStatus"), "the status is RobotInfo, as in ARIA");
      assertTrue(
          Futures.failure(visitor.requestOnce("mappingStart", "x"))
              .getMessage()
              .contains("no data 'mappingStart'"));
      ServerStats stats = r.rig.gui.getServer().getStats();
      long before = stats.getRequestErrors();
      assertEquals(Protocol.SERVER_CONNECTED, raw.login("visitor", "look").getCommand());
      ArNetPacket body = new ArNetPacket();
      body.strToBuf("sneaky");
      raw.requestOnce(r.rig.gui.getServer().findCommandFromName("mappingStart"), body);
      raw.requestOnce(
          r.rig.gui.getServer().findCommandFromName("mappingStatus"), new ArNetPacket());
      assertEquals(
          "", raw.readUntil(r.rig.gui.getServer().findCommandFromName("mappingStatus")).bufToStr());
      assertEquals(before + 1, stats.getRequestErrors(), "refused and counted");
      assertFalse(Files.exists(dir.resolve("sneaky.2d")));
      mapper.connect("127.0.0.1", port, "mapper", "pw");
      assertEquals(0, r.rig.await(mapper.requestOnce("mappingStart", "allowed")).bufToByte());
    }
  }

  /**
   * The bytes on the wire, as ArNetworking lays them out (ARIA 2.9.1's server writes them so):
   * mappingStart answers one byte, mappingEnd two bytes for an ended scan and one for none,
   * mappingStatus a zero-ended string.
   */
  @Test
  void theRepliesAreArNetworkingsBytes(@TempDir Path dir) throws Exception {
    try (Rig r = new Rig(dir);
        RawClient aria = new RawClient(r.rig.gui.getServer().getPort())) {
      ArServerBase s = r.rig.gui.getServer();
      int start = s.findCommandFromName("mappingStart");
      int end = s.findCommandFromName("mappingEnd");
      int status = s.findCommandFromName("mappingStatus");
      assertEquals(Protocol.SERVER_CONNECTED, aria.login("", "").getCommand());
      byte[] request = {
        0x0F, 0x0C, 13, 0, (byte) start, (byte) (start >> 8), 'h', 'a', 'l', 'l', 0
      };
      aria.send(withChecksum(request));
      assertArrayEquals(
          withChecksum(new byte[] {0x0F, 0x0C, 9, 0, (byte) start, (byte) (start >> 8), 0}),
          aria.readUntil(start).toWire());
      aria.send(withChecksum(new byte[] {0x0F, 0x0C, 8, 0, (byte) status, (byte) (status >> 8)}));
      assertArrayEquals(
          withChecksum(
              new byte[] {
                0x0F, 0x0C, 13, 0, (byte) status, (byte) (status >> 8), 'h', 'a', 'l', 'l', 0
              }),
          aria.readUntil(status).toWire());
      aria.send(withChecksum(new byte[] {0x0F, 0x0C, 8, 0, (byte) end, (byte) (end >> 8)}));
      assertArrayEquals(
          withChecksum(new byte[] {0x0F, 0x0C, 10, 0, (byte) end, (byte) (end >> 8), 0, 0}),
          aria.readUntil(end).toWire());
      aria.send(withChecksum(new byte[] {0x0F, 0x0C, 8, 0, (byte) end, (byte) (end >> 8)}));
      assertArrayEquals(
          withChecksum(new byte[] {0x0F, 0x0C, 9, 0, (byte) end, (byte) (end >> 8), 1}),
          aria.readUntil(end).toWire());
      assertTrue(Files.isRegularFile(dir.resolve("hall.2d")));
    }
  }

  /**
   * {@code body} (header, command, data) with ArNetworking's checksum appended (its odd algorithm
   * is {@link ArNetPacket#checksum}'s, checked against ARIA's recordings elsewhere).
   */
  private static byte[] withChecksum(byte[] body) {
    byte[] w = java.util.Arrays.copyOf(body, body.length + 2);
    int c = ArNetPacket.checksum(w, body.length);
    w[body.length] = (byte) (c >> 8);
    w[body.length + 1] = (byte) c;
    return w;
  }

  private static List<Path> listing(Path dir) throws Exception {
    try (Stream<Path> s = Files.list(dir)) {
      return s.toList();
    }
  }
}
