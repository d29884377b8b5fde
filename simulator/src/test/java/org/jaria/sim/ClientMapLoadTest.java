package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.sim.server.IgnoredCommand;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Hostile SIM_CTRL map loads and the commands a user can switch off: every bad request gets status
 * -1, the robots keep being served, nothing of a file's content reaches the log.
 */
class ClientMapLoadTest {

  private static final String BOX =
      """
      2D-Map
      Cairn: RobotHome 5000 5000 90 "" ICON ""
      LINES
      0 0 10000 0
      10000 0 10000 10000
      10000 10000 0 10000
      0 10000 0 0
      DATA
      """;

  private static SimOptions inFolder(Path dir, long maxBytes) {
    return SimOptions.builder()
        .watchdogMillis(0)
        .server(SimServerOptions.DEFAULTS.withMapFolder(dir, maxBytes))
        .build();
  }

  /** Sends SIM_CTRL 1 {@code name} and returns the status of the SIM_MAP_CHANGED answer. */
  private static int load(SimWorld w, ArcosTestClient c, String name) throws Exception {
    byte[] raw = name.getBytes(StandardCharsets.ISO_8859_1);
    ByteBuffer b = ByteBuffer.allocate(5 + raw.length).order(ByteOrder.LITTLE_ENDIAN);
    b.put((byte) 0x3B).putShort((short) 1).putShort((short) raw.length).put(raw);
    c.clear();
    c.comPayload(ArCommands.SIM_CTRL, b.array());
    w.step();
    w.awaitClientMapLoad();
    ArRobotPacket changed = c.awaitId(PacketIds.SIM_MAP_CHANGED);
    changed.resetRead();
    changed.bufToUByte();
    return changed.bufToByte();
  }

  @Test
  void pathsOutsideTheFolderDevicesFifosAndHugeFilesAreRefusedAndRobotsKeepRunning(
      @TempDir Path tmp) throws Exception {
    Path dir = Files.createDirectories(tmp.resolve("maps"));
    Files.writeString(tmp.resolve("outside.map"), BOX);
    Files.writeString(dir.resolve("box.map"), BOX);
    Files.writeString(dir.resolve("big.map"), BOX + "0 0\n".repeat(1000));
    Files.createSymbolicLink(dir.resolve("zero.map"), Path.of("/dev/zero"));
    Files.createSymbolicLink(dir.resolve("out.map"), tmp.resolve("outside.map"));
    Process mk = new ProcessBuilder("mkfifo", dir.resolve("fifo.map").toString()).start();
    assertEquals(0, mk.waitFor(), "mkfifo");
    try (SimWorld w = SimWorld.empty(inFolder(dir, 1000))) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      for (String bad :
          List.of(
              "/dev/zero",
              "/etc/shadow",
              "/etc/passwd",
              tmp.resolve("outside.map").toString(),
              "../outside.map",
              "sub/../../outside.map",
              "zero.map",
              "out.map",
              "fifo.map",
              "big.map",
              "missing.map",
              "",
              ".")) {
        assertEquals(-1, load(w, c, bad), "status for " + bad);
        assertTrue(r.isSessionOpen(), "still served after " + bad);
      }
      long sips = c.received.stream().filter(p -> PacketIds.isStandardSip(p.getID())).count();
      w.advanceMillis(500);
      assertTrue(
          c.received.stream().filter(p -> PacketIds.isStandardSip(p.getID())).count() >= sips + 4,
          "SIPs keep coming");
      assertEquals(1, load(w, c, "box.map"), "a good map inside the folder loads");
      assertEquals(new ArPose(5000, 5000, 90), r.getTruePose());
    }
  }

  @Test
  void aMapOverTheBudgetIsRefusedAndTheWorldKeepsItsMap(@TempDir Path dir) throws Exception {
    MapBudgetTest.writeLongWalls(dir.resolve("long-walls.map"));
    Files.writeString(dir.resolve("box.map"), BOX);
    try (SimWorld w = SimWorld.empty(inFolder(dir, 64L << 20))) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      assertEquals(-1, load(w, c, "long-walls.map"), "under the byte limit, over the budget");
      assertFalse(w.haveMap(), "nothing of it was built");
      assertTrue(r.isSessionOpen());
      assertEquals(1, load(w, c, "box.map"), "the next map loads as usual");
    }
  }

  @Test
  void aFileThatIsNotAMapNeverReachesTheLog(@TempDir Path dir) throws Exception {
    Files.writeString(dir.resolve("secret.map"), "TOPSECRET-FIRST-LINE hunter2\nmore\n");
    PrintStream old = System.err;
    ByteArrayOutputStream captured = new ByteArrayOutputStream();
    System.setErr(new PrintStream(captured, true, StandardCharsets.UTF_8));
    try (SimWorld w = SimWorld.empty(inFolder(dir, 1 << 20))) {
      ArcosTestClient c = new ArcosTestClient(w, w.addRobot("p3dx-sh")).open();
      assertEquals(-1, load(w, c, "secret.map"));
    } finally {
      System.setErr(old);
    }
    String log = captured.toString(StandardCharsets.UTF_8);
    assertTrue(log.contains("secret.map"), "the refusal is logged: " + log);
    assertFalse(log.contains("TOPSECRET"), "file contents in the log: " + log);
    assertFalse(log.contains("hunter2"), "file contents in the log: " + log);
  }

  @Test
  void withoutAMapFolderAbsolutePathsAreRefusedToo() throws Exception {
    try (SimWorld w = SimWorld.empty(SimOptions.builder().watchdogMillis(0).build())) {
      ArcosTestClient c = new ArcosTestClient(w, w.addRobot("p3dx-sh")).open();
      assertEquals(-1, load(w, c, "/etc/passwd"));
      assertEquals(-1, load(w, c, "../../../../../../../../etc/passwd"));
    }
  }

  @Test
  void ignoredCommandsAreNotCarriedOutAndAreCounted() {
    SimOptions o =
        SimOptions.builder()
            .watchdogMillis(0)
            .server(SimServerOptions.DEFAULTS.withIgnoredCommands(Set.of(239, 224)))
            .build();
    try (SimWorld w = SimWorld.empty(o)) {
      AtomicInteger exit = new AtomicInteger(-1);
      w.setExitHandler(exit::set);
      SimRobot r = w.addRobot("p3dx-sh");
      ArPose start = r.getTruePose();
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.SIM_EXIT, 3);
      ByteBuffer b = ByteBuffer.allocate(13).order(ByteOrder.LITTLE_ENDIAN);
      b.put((byte) 0x3B).putInt(1000).putInt(2000).putInt(45);
      c.comPayload(ArCommands.SIM_SET_POSE, b.array());
      w.advanceMillis(100);
      assertEquals(-1, exit.get(), "SIM_EXIT ignored");
      assertEquals(start, r.getTruePose(), "SIM_SET_POSE ignored");
      assertTrue(r.isSessionOpen());
      assertEquals(
          List.of(
              new IgnoredCommand(224, "SIM_SET_POSE", IgnoredCommand.Reason.BY_OPTION, 1),
              new IgnoredCommand(239, "SIM_EXIT", IgnoredCommand.Reason.BY_OPTION, 1)),
          w.getIgnoredCommands());
    }
  }
}
