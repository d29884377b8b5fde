package org.jaria.action;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.jaria.action.ArResolver.PrioritizedAction;
import org.jaria.geom.ArPose;
import org.jaria.input.ArKeyHandler;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.testing.LockstepRig;

/**
 * Measures the action resolver, and a whole robot cycle (sensor interpretation, resolver, state
 * reflection), with 20 active actions on a connected robot with sonar readings. Prints; asserts
 * nothing. Run with:
 *
 * <pre>
 * ./mvnw -q -o -Djaria.target=target-x -pl aria-core test-compile dependency:build-classpath \
 *     -Dmdep.includeScope=test -Dmdep.outputFile=/tmp/cp.txt
 * java -cp aria-core/target-x/test-classes:aria-core/target-x/classes:$(cat /tmp/cp.txt) \
 *     org.jaria.action.ResolverBenchmark
 * </pre>
 */
public final class ResolverBenchmark {

  private ResolverBenchmark() {}

  /** Runs the benchmark and prints the figures. */
  public static void main(String[] args) {
    LockstepRig rig = new LockstepRig();
    rig.robot.addRangeDevice(new ArSonarDevice());
    if (!rig.connect()) {
      throw new IllegalStateException("the rig did not connect");
    }
    ArRobot robot = rig.robot;
    for (ArAction a : twentyActions()) {
      robot.addAction(a, 100 - robot.getActionList().size() * 4);
    }
    rig.robot.setCycleWarningTime(0);
    for (int i = 0; i < 16; i++) {
      rig.sip.addSonar(i, 600 + 150 * i);
    }
    rig.run(1000);

    List<PrioritizedAction> list = robot.getActionList();
    ArPriorityResolver resolver = new ArPriorityResolver();
    int n = 200_000;
    for (int i = 0; i < n; i++) {
      resolver.resolve(list, robot);
    }
    long[] resolve = new long[n];
    for (int i = 0; i < n; i++) {
      long t0 = System.nanoTime();
      resolver.resolve(list, robot);
      resolve[i] = System.nanoTime() - t0;
    }

    int cycles = 20_000;
    for (int i = 0; i < cycles / 4; i++) {
      rig.run(100);
    }
    long[] cycle = new long[cycles];
    for (int i = 0; i < cycles; i++) {
      rig.run(100);
      cycle[i] = robot.getLastCycleNanos();
    }
    System.out.println(
        "actions: " + list.size() + " active, " + robot.getActionDesired() + " last desire");
    print("resolver alone      ", resolve);
    print("whole cycle (loopOnce: sensors + resolver + state reflection)", cycle);
  }

  private static void print(String what, long[] ns) {
    long[] s = ns.clone();
    Arrays.sort(s);
    double mean = Arrays.stream(s).average().orElse(0);
    System.out.printf(
        Locale.ROOT,
        "%s: median %.2f us, p99 %.2f us, mean %.2f us (%d samples)%n",
        what,
        s[s.length / 2] / 1e3,
        s[(int) (s.length * 0.99)] / 1e3,
        mean / 1e3,
        s.length);
  }

  private static List<ArAction> twentyActions() {
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
