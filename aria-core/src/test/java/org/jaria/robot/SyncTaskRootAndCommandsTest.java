package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.protocol.ArCommands;
import org.jaria.range.ArBumpers;
import org.jaria.range.ArSonarDevice;
import org.jaria.testing.FakeRobot;
import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.Test;

/** ARIA's view of the cycle as a task tree, and the smaller ARIA API pieces. */
class SyncTaskRootAndCommandsTest {

  private final LockstepRig rig = new LockstepRig();

  private static List<String> names(SyncTaskView node) {
    return node.children().stream().map(SyncTaskView::name).toList();
  }

  @Test
  void theTreeShowsTheCycleInRunningOrderWithTheTasksInTheirBranches() {
    rig.robot.addRangeDevice(new ArSonarDevice());
    rig.robot.addRangeDevice(new ArBumpers());
    rig.robot.addUserTask("late", 10, () -> {});
    rig.robot.addUserTask("early", 90, () -> {});

    SyncTaskView root = rig.robot.getSyncTaskRoot();
    assertEquals("SyncTasks", root.name());
    assertTrue(root.branch());
    assertEquals(
        List.of(
            "Packet Handler", "Sensor Interp", "Action Handler", "State Reflector", "User Tasks"),
        names(root));
    assertEquals(
        List.of(85, 65, 55, 45, 25), root.children().stream().map(SyncTaskView::position).toList());
    assertEquals(List.of("sonar", "bumpers"), names(root.find("Sensor Interp")));
    assertEquals(List.of("early", "late"), names(root.find("User Tasks")));
    assertEquals(90, root.find("early").position());
    assertFalse(root.find("early").branch());
    assertNull(root.find("Action Handler").task(), "built-in steps have no task object");
    assertTrue(root.find("Action Handler").isActive());
    assertNull(root.find("no such task"));

    String printed = root.toString();
    assertTrue(printed.startsWith("SyncTasks (0)\n  Packet Handler (85)\n"), printed);
    assertTrue(printed.contains("\n    early (90) ACTIVE\n"), printed);
  }

  @Test
  void aTaskFoundInTheTreeIsTheLiveTask() {
    assertTrue(rig.connect());
    AtomicInteger runs = new AtomicInteger();
    rig.robot.addUserTask("count", 50, runs::incrementAndGet);
    SyncTaskView node = rig.robot.getSyncTaskRoot().find("count");
    assertSame(rig.robot.findUserTask("count"), node.task());
    rig.run(300);
    int before = runs.get();
    assertTrue(before > 0);
    node.task().setState(ArSyncTask.State.SUSPEND);
    assertFalse(rig.robot.getSyncTaskRoot().find("count").isActive());
    rig.run(300);
    assertEquals(before, runs.get(), "suspended through the tree");
  }

  @Test
  void theTreeIsASnapshot() {
    SyncTaskView before = rig.robot.getSyncTaskRoot();
    rig.robot.addUserTask("added later", 1, () -> {});
    assertTrue(before.find("User Tasks").children().isEmpty());
    assertTrue(before.find("User Tasks").branch(), "an empty branch is still a branch");
    assertEquals(1, rig.robot.getSyncTaskRoot().find("User Tasks").children().size());
  }

  @Test
  void comStrNByNumberPadsOrCutsToTheSize() {
    assertTrue(rig.connect());
    rig.fake.clearReceived();
    int lcd = ArCommands.LCDWRITE.getNumber();
    assertTrue(rig.robot.comStrN(lcd, "hello", 8));
    assertTrue(rig.robot.comStrN(lcd, "toolongstring", 4));
    rig.run(10);
    List<FakeRobot.Received> got = rig.fake.received(ArCommands.LCDWRITE);
    assertEquals(2, got.size());
    assertEquals("FA FB 0D 3B 2B 08 68 65 6C 6C 6F 00 00 00 15 6E", got.get(0).hex());
    assertEquals("FA FB 09 3B 2B 04 74 6F 6F 6C AF 62", got.get(1).hex());
  }

  @Test
  void eStallIsTheSpecsNameForCommand56AndAriasNamesWork() {
    assertSame(ArCommands.M_STALL, ArCommands.E_STALL);
    assertEquals(56, ArCommands.E_STALL.getNumber());
    assertSame(ArCommands.E_STALL, ArCommands.fromNumber(56));
    assertSame(ArCommands.M_STALL, ArCommands.ESTALL, "ARIA's spelling");
    assertSame(ArCommands.E_STOP, ArCommands.ESTOP, "ARIA's spelling");
    assertNull(ArCommands.fromNumber(34), "34 (KICK) is not in the spec's command list");
  }
}
