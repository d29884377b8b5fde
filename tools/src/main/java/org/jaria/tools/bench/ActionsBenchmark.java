package org.jaria.tools.bench;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionAvoidFront;
import org.jaria.action.ArActionAvoidSide;
import org.jaria.action.ArActionBumpers;
import org.jaria.action.ArActionConstantVelocity;
import org.jaria.action.ArActionDeceleratingLimiter;
import org.jaria.action.ArActionGoto;
import org.jaria.action.ArActionGotoStraight;
import org.jaria.action.ArActionInput;
import org.jaria.action.ArActionJoydrive;
import org.jaria.action.ArActionKeydrive;
import org.jaria.action.ArActionLimiterBackwards;
import org.jaria.action.ArActionLimiterForwards;
import org.jaria.action.ArActionLimiterRot;
import org.jaria.action.ArActionLimiterTableSensor;
import org.jaria.action.ArActionMovementParameters;
import org.jaria.action.ArActionRatioInput;
import org.jaria.action.ArActionStallRecover;
import org.jaria.action.ArActionTurn;
import org.jaria.action.ArPriorityResolver;
import org.jaria.action.ArResolver.PrioritizedAction;
import org.jaria.geom.ArPose;
import org.jaria.input.ArKeyHandler;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.sim.client.SimulatedRobot;

/**
 * {@code jaria bench actions}: the cost of the action machinery per cycle with 20 active actions
 * (ARIA's predefined ones, as a busy program would have) on a P3-DX driving in the simulated office
 * with 16 sonars: the priority resolver alone, and the robot's whole cycle (SIP handling, sensor
 * interpretation, resolver, state reflection). The simulator runs in lockstep; only the client's
 * work is timed.
 */
public final class ActionsBenchmark {

  private ActionsBenchmark() {}

  /** Runs the benchmark and returns its table. */
  public static String run(boolean quick) {
    try (SimulatedRobot sim = SimulatedRobot.start("office", "p3dx-sh", 1)) {
      ArRobot robot = sim.robot();
      robot.addRangeDevice(new ArSonarDevice());
      List<ArAction> actions = twentyActions();
      for (int i = 0; i < actions.size(); i++) {
        robot.addAction(actions.get(i), 100 - 4 * i);
      }
      robot.setCycleWarningTime(0);
      robot.enableMotors();
      sim.runMillis(2_000);

      List<PrioritizedAction> list = robot.getActionList();
      ArPriorityResolver resolver = new ArPriorityResolver();
      int n = quick ? 20_000 : 200_000;
      for (int i = 0; i < n; i++) {
        resolver.resolve(list, robot);
      }
      long[] resolve = new long[n];
      for (int i = 0; i < n; i++) {
        long t0 = System.nanoTime();
        resolver.resolve(list, robot);
        resolve[i] = System.nanoTime() - t0;
      }

      int cycles = quick ? 2_000 : 20_000;
      for (int i = 0; i < cycles / 4; i++) {
        sim.runMillis(100);
      }
      long[] cycle = new long[cycles];
      for (int i = 0; i < cycles; i++) {
        sim.runMillis(100);
        cycle[i] = robot.getLastCycleNanos();
      }
      StringBuilder out = new StringBuilder();
      out.append(
          String.format(
              Locale.ROOT,
              "JAria actions benchmark (%s): %d active actions, 16 sonars, office map%n",
              quick ? "quick" : "full",
              list.size()));
      out.append(
          String.format(
              Locale.ROOT,
              "%-44s %10s %10s %10s %9s%n",
              "measure",
              "median",
              "p99",
              "mean",
              "samples"));
      row(out, "resolver alone", resolve);
      row(out, "whole cycle (sensors+resolver+reflection)", cycle);
      return out.toString();
    }
  }

  private static void row(StringBuilder out, String what, long[] ns) {
    long[] s = ns.clone();
    Arrays.sort(s);
    double mean = Arrays.stream(s).average().orElse(0);
    out.append(
        String.format(
            Locale.ROOT,
            "%-44s %7.2f us %7.2f us %7.2f us %9d%n",
            what,
            s[s.length / 2] / 1e3,
            s[(int) (s.length * 0.99)] / 1e3,
            mean / 1e3,
            s.length));
  }

  /** Twenty of ARIA's predefined actions, configured as a real program might. */
  static List<ArAction> twentyActions() {
    List<ArAction> l = new ArrayList<>();
    l.add(new ArActionStallRecover());
    l.add(new ArActionBumpers());
    l.add(new ArActionLimiterTableSensor());
    l.add(new ArActionLimiterForwards("Speed Limiter Near", 300, 600, 250));
    l.add(new ArActionLimiterForwards("Speed Limiter Far", 300, 1100, 400));
    l.add(new ArActionLimiterBackwards());
    l.add(new ArActionDeceleratingLimiter());
    l.add(new ArActionAvoidFront("Avoid Front Near", 225, 0));
    l.add(new ArActionAvoidFront());
    l.add(new ArActionAvoidSide());
    ArActionLimiterRot rot = new ArActionLimiterRot();
    rot.setParameters(true, 10);
    l.add(rot);
    ArActionMovementParameters mp = new ArActionMovementParameters();
    mp.setParameters(600, 300, 300, 400, 90, 100, 100);
    l.add(mp);
    l.add(new ArActionTurn());
    l.add(new ArActionKeydrive(new ArKeyHandler()));
    l.add(new ArActionJoydrive());
    ArActionRatioInput ratio = new ArActionRatioInput();
    ratio.setRatios(50, 10, 80);
    l.add(ratio);
    ArActionInput in = new ArActionInput();
    in.setVel(200);
    in.setRotVel(5);
    l.add(in);
    l.add(new ArActionGoto("goto", new ArPose(5000, 2000), 100, 400, 150, 7));
    l.add(new ArActionGotoStraight());
    l.add(new ArActionConstantVelocity());
    return l;
  }
}
