package org.jaria.tools.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.sim.OdometryError;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.robot.SimProfile;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;

/**
 * Which profile a command line gets: {@code --profile} when given, else {@code mobilesim} for
 * MobileSim's own command line and {@code pioneer} for JAria's.
 */
class SimProfileCommandLineTest {

  private static SimCommand parse(String... args) {
    SimCommand cmd = new SimCommand();
    new CommandLine(cmd).parseArgs(args);
    return cmd;
  }

  @Test
  void jariasOwnCommandLineGetsThePioneerProfile() {
    assertEquals(SimProfile.PIONEER, parse().profile());
    assertEquals(SimProfile.PIONEER, parse("--map", "hall", "--robot", "p3at-sh").profile());
    assertEquals(SimProfile.PIONEER, parse("-p", "8101", "--laser", "--seed", "3").profile());
    SimOptions o = parse("--map", "hall").buildOptions();
    assertEquals(OdometryError.NONE, o.odometryError());
    assertTrue(o.sonar().specular());
  }

  @Test
  void mobileSimsOwnCommandLineGetsTheMobileSimProfile() {
    for (List<String> args :
        List.of(
            List.of("-m", "office"),
            List.of("-map", "office"),
            List.of("-r", "p3dx"),
            List.of("--map", "office", "--nogui"),
            List.of("--nomap"),
            List.of("--start", "outside"),
            List.of("--no-error"),
            List.of("--odom-error-mode=none"),
            List.of("--ignore-command", "239"))) {
      SimCommand cmd = parse(args.toArray(String[]::new));
      assertEquals(SimProfile.MOBILESIM, cmd.profile(), args.toString());
    }
    SimOptions o = parse("-m", "office").buildOptions();
    assertEquals(SimProfile.MOBILESIM, o.profile());
    assertEquals(SimProfile.MOBILESIM_ODOMETRY, o.odometryError(), "MobileSim's drift");
    assertTrue(o.sonar().allEachSip());
  }

  @Test
  void profileOptionWinsAndOdometryOptionsOverrideTheProfilesDrift() {
    assertEquals(SimProfile.PIONEER, parse("-m", "office", "--profile", "pioneer").profile());
    assertEquals(SimProfile.MOBILESIM, parse("--profile", "mobilesim").profile());
    assertEquals(
        OdometryError.NONE,
        parse("--profile", "mobilesim", "--no-error").buildOptions().odometryError());
    assertEquals(
        OdometryError.randomInit(0.0075, 0.0075),
        parse("-m", "office", "--odom-error-mode", "random_init").buildOptions().odometryError());
    assertEquals(
        OdometryError.random(0.02, 0.05),
        parse("-m", "office", "--odometry-error", "random:0.02,0.05")
            .buildOptions()
            .odometryError());
    ParameterException e =
        assertThrows(ParameterException.class, () -> parse("--profile", "stage").profile());
    assertTrue(e.getMessage().contains("mobilesim"), e.getMessage());
    e =
        assertThrows(
            ParameterException.class, () -> parse("--odom-error-mode", "sometimes").buildOptions());
    assertTrue(e.getMessage().contains("random_each_update"), e.getMessage());
  }

  @Test
  void startAppliesToEveryRobotInMobileSimsRow() throws IOException {
    SimCommand cmd =
        parse(
            "-m",
            "office",
            "-r",
            "p3dx",
            "-r",
            "p3dx",
            "-r",
            "amigo",
            "-p",
            "0",
            "--start",
            "1000,2000,90");
    try (SimWorld w = cmd.createWorld()) {
      List<SimRobot> r = w.getRobots();
      assertEquals(new ArPose(1000, 2000, 90), r.get(0).getTruePose());
      assertEquals(new ArPose(1000, 1000, 90), r.get(1).getTruePose(), "1 m below the first");
      assertEquals(new ArPose(1000, 0, 90), r.get(2).getTruePose());
    }
    SimCommand pioneer =
        parse("--profile", "pioneer", "--robots", "2", "-p", "0", "--start", "1000,2000,90");
    try (SimWorld w = pioneer.createWorld()) {
      assertEquals(new ArPose(1000, 1000, 90), w.getRobots().get(1).getTruePose(), "both profiles");
    }
  }

  @Test
  void withoutStartMobileSimsRobotsStandInARowBelowTheHome() throws IOException {
    try (SimWorld w = parse("-m", "hall", "-r", "p3dx", "-r", "p3dx", "-p", "0").createWorld()) {
      ArPose home = w.getMap().home();
      ArPose second = w.getRobots().get(1).getTruePose();
      assertEquals(new ArPose(home.x(), home.y() - 1000, home.th()), second);
      assertFalse(w.getRobots().get(0).getModel().getSubtype().isEmpty());
    }
  }

  @Test
  void mobileSimProfileRobotsHaveNoGripperAndPioneersDo() throws IOException {
    try (SimWorld w = parse("-m", "office", "-p", "0").createWorld()) {
      assertEquals(0, w.getRobots().get(0).getGripState());
    }
    assertTrue(parse("--robot", "p3dx-sh").robotOptions("p3dx-sh").gripper());
    assertFalse(parse("-r", "p3dx-sh").robotOptions("p3dx-sh").gripper());
  }

  @Test
  void theSummarySaysHowFarEachRobotDroveApartFromHowFarItIsFromTheStart() throws IOException {
    try (SimWorld w = parse("--map", "hall", "-p", "0").createWorld()) {
      SimRobot r = w.getRobots().get(0);
      ArPose s = r.getStartPose();
      r.setTruePose(new ArPose(s.x() + 1000, s.y(), s.th())); // carried, not driven
      StringWriter out = new StringWriter();
      SimCommand.printSummary(w, new PrintWriter(out, true));
      assertTrue(
          out.toString().contains("moved 1000 mm from the start; drove 0 mm;"), out.toString());
    }
  }
}
