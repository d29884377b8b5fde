package org.jaria.web.control;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.List;
import org.jaria.geom.ArPose;
import org.junit.jupiter.api.Test;

/** Viewers' commands are read with limits and carried out only where a control exists. */
class ControlCommandTest {

  static ControlCommand parse(String topic, String json) {
    return ControlCommand.parse(topic, json.getBytes(StandardCharsets.UTF_8));
  }

  @Test
  void aTwistDrivesInMillimetresAndDegreesWithinLimits() {
    assertEquals(
        new ControlCommand.Drive(400, Math.toDegrees(0.5)),
        parse("/cmd_vel", "{\"linear\":{\"x\":0.4},\"angular\":{\"z\":0.5}}"));
    ControlCommand fast = parse("/cmd_vel", "{\"linear\":{\"x\":99},\"angular\":{\"z\":-99}}");
    assertEquals(
        new ControlCommand.Drive(ControlCommand.MAX_VEL, -ControlCommand.MAX_ROT_VEL), fast);
    assertInstanceOf(ControlCommand.Invalid.class, parse("/cmd_vel", "{\"linear\":{}}"));
  }

  @Test
  void aGoalIsAPoseInMetresWithAnOptionalHeading() {
    assertEquals(
        new ControlCommand.Goal(new ArPose(1500, -2000, 0), false),
        parse("/goal", "{\"pose\":{\"position\":{\"x\":1.5,\"y\":-2}}}"));
    ControlCommand g =
        parse(
            "/goal",
            "{\"pose\":{\"position\":{\"x\":1,\"y\":2},\"orientation\":{\"x\":0,\"y\":0,"
                + "\"z\":0.7071068,\"w\":0.7071068}}}");
    ControlCommand.Goal goal = assertInstanceOf(ControlCommand.Goal.class, g);
    assertTrue(goal.useHeading());
    assertEquals(90, goal.pose().th(), 1e-4);
    assertInstanceOf(
        ControlCommand.Invalid.class,
        parse("/goal", "{\"pose\":{\"position\":{\"x\":1e12,\"y\":0}}}"));
    assertInstanceOf(ControlCommand.Invalid.class, parse("/goal", "{}"));
  }

  @Test
  void simulationCommandsAreChecked() {
    assertEquals(
        new ControlCommand.Sim(ControlCommand.SimAction.PAUSE, 0),
        parse("/sim/control", "{\"command\":\"pause\"}"));
    assertEquals(
        new ControlCommand.Sim(ControlCommand.SimAction.STEP, 100),
        parse("/sim/control", "{\"command\":\"step\",\"value\":100}"));
    assertInstanceOf(
        ControlCommand.Invalid.class,
        parse("/sim/control", "{\"command\":\"step\",\"value\":1e9}"));
    assertInstanceOf(
        ControlCommand.Invalid.class, parse("/sim/control", "{\"command\":\"speed\",\"value\":0}"));
    assertInstanceOf(
        ControlCommand.Invalid.class, parse("/sim/control", "{\"command\":\"reboot\"}"));
    assertInstanceOf(ControlCommand.Invalid.class, parse("/elsewhere", "{}"));
    assertInstanceOf(ControlCommand.Invalid.class, parse("/cmd_vel", "nonsense"));
  }

  @Test
  void commandsGoToTheControlsThatExist() {
    RecordingControls r = new RecordingControls();
    Controls both = new Controls(r, r);
    assertNull(ControlCommand.apply(new ControlCommand.Drive(100, 10), both));
    assertNull(
        ControlCommand.apply(new ControlCommand.Sim(ControlCommand.SimAction.STEP, 50), both));
    assertNull(
        ControlCommand.apply(new ControlCommand.Sim(ControlCommand.SimAction.SPEED, 2), both));
    r.acceptGoals = false;
    String refused = ControlCommand.apply(new ControlCommand.Goal(new ArPose(1, 2), false), both);
    assertTrue(refused.startsWith("no path to 1, 2"), refused);
    assertEquals(
        List.of("drive 100.0 10.0", "step 50", "speed 2.0", "goto " + new ArPose(1, 2)), r.calls);
    assertEquals("drive,goal,sim", both.describe());
    String none = ControlCommand.apply(new ControlCommand.Drive(1, 1), new Controls(null, r));
    assertTrue(none.contains("no robot"), none);
    String noSim =
        ControlCommand.apply(
            new ControlCommand.Sim(ControlCommand.SimAction.RUN, 0), new Controls(r, null));
    assertTrue(noSim.contains("no simulation"), noSim);
    assertEquals("", Controls.NONE.describe());
  }
}
