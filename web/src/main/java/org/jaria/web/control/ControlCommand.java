package org.jaria.web.control;

import java.nio.charset.StandardCharsets;
import java.util.Map;
import org.jaria.geom.ArPose;
import org.jaria.web.json.JsonValues;

/**
 * A command a viewer publishes, read from its topic and JSON payload:
 *
 * <ul>
 *   <li>{@value #DRIVE_TOPIC}: a Twist, {@code {"linear":{"x":m/s},"angular":{"z":rad/s}}} (what
 *       Foxglove's Teleop panel sends);
 *   <li>{@value #GOAL_TOPIC}: a pose, {@code {"pose":{"position":{"x":m,"y":m},
 *       "orientation":{...}}}} (what Foxglove's 3D panel's "publish pose" sends), heading used only
 *       when the orientation is given;
 *   <li>{@value #SIM_TOPIC}: {@code {"command":"run"|"pause"|"step"|"speed", "value":n}}.
 * </ul>
 *
 * Values are limited to what a robot can do; anything else is {@link Invalid}.
 */
public sealed interface ControlCommand {

  /** Topic of drive commands. */
  String DRIVE_TOPIC = "/cmd_vel";

  /** Topic of goals. */
  String GOAL_TOPIC = "/goal";

  /** Topic of simulation commands. */
  String SIM_TOPIC = "/sim/control";

  /** How long a drive command holds before the robot stops by itself, ms. */
  long DRIVE_HOLD_MILLIS = 600;

  /** Fastest drive a viewer may ask for, mm/s. */
  double MAX_VEL = 1500;

  /** Fastest turn a viewer may ask for, deg/s. */
  double MAX_ROT_VEL = 180;

  /** Largest speed-up a viewer may set. */
  double MAX_SPEEDUP = 50;

  /** Longest single step, ms. */
  long MAX_STEP_MILLIS = 10_000;

  /** Farthest goal from the origin, mm (a map is never this large). */
  double MAX_COORDINATE = 1e7;

  /**
   * Drive.
   *
   * @param vel mm/s
   * @param rotVel deg/s
   */
  record Drive(double vel, double rotVel) implements ControlCommand {}

  /**
   * Go to a pose.
   *
   * @param pose where, mm and degrees
   * @param useHeading whether to turn to its heading
   */
  record Goal(ArPose pose, boolean useHeading) implements ControlCommand {}

  /** Simulation commands. */
  enum SimAction {
    /** Run. */
    RUN,
    /** Pause. */
    PAUSE,
    /** Step while paused. */
    STEP,
    /** Set the speed-up. */
    SPEED
  }

  /**
   * A simulation command.
   *
   * @param action what
   * @param value the step in ms, or the speed-up
   */
  record Sim(SimAction action, double value) implements ControlCommand {}

  /**
   * Not a command.
   *
   * @param reason what is wrong
   */
  record Invalid(String reason) implements ControlCommand {}

  /** Reads the command {@code payload} carries on {@code topic}. */
  static ControlCommand parse(String topic, byte[] payload) {
    Object v;
    try {
      v = JsonValues.read(new String(payload, StandardCharsets.UTF_8));
    } catch (JsonValues.BadJson e) {
      return new Invalid(e.getMessage());
    }
    if (!(v instanceof Map<?, ?> m)) {
      return new Invalid("a command is a JSON object");
    }
    return switch (topic) {
      case DRIVE_TOPIC -> drive(m);
      case GOAL_TOPIC -> goal(m);
      case SIM_TOPIC -> sim(m);
      default -> new Invalid("nothing listens on " + topic);
    };
  }

  private static ControlCommand drive(Map<?, ?> m) {
    double x = number(m, "linear", "x");
    double z = number(m, "angular", "z");
    if (!Double.isFinite(x) || !Double.isFinite(z)) {
      return new Invalid("a drive command needs linear.x (m/s) and angular.z (rad/s)");
    }
    double vel = clamp(x * 1000, MAX_VEL);
    double rot = clamp(Math.toDegrees(z), MAX_ROT_VEL);
    return new Drive(vel, rot);
  }

  private static ControlCommand goal(Map<?, ?> m) {
    Object pose = m.get("pose");
    if (!(pose instanceof Map<?, ?> p)) {
      return new Invalid("a goal needs a pose");
    }
    double x = number(p, "position", "x") * 1000;
    double y = number(p, "position", "y") * 1000;
    if (!Double.isFinite(x)
        || !Double.isFinite(y)
        || Math.abs(x) > MAX_COORDINATE
        || Math.abs(y) > MAX_COORDINATE) {
      return new Invalid("a goal needs pose.position.x and .y in metres, on the map");
    }
    double qz = number(p, "orientation", "z");
    double qw = number(p, "orientation", "w");
    boolean heading = Double.isFinite(qz) && Double.isFinite(qw) && (qz != 0 || qw != 0);
    double th = heading ? Math.toDegrees(2 * Math.atan2(qz, qw)) : 0;
    return new Goal(new ArPose(x, y, th), heading && !Boolean.FALSE.equals(m.get("heading")));
  }

  private static ControlCommand sim(Map<?, ?> m) {
    Object c = m.get("command");
    double value = m.get("value") instanceof Number n ? n.doubleValue() : Double.NaN;
    if (!(c instanceof String command)) {
      return new Invalid("a simulation command needs \"command\"");
    }
    return switch (command) {
      case "run" -> new Sim(SimAction.RUN, 0);
      case "pause" -> new Sim(SimAction.PAUSE, 0);
      case "step" ->
          value > 0 && value <= MAX_STEP_MILLIS
              ? new Sim(SimAction.STEP, Math.rint(value))
              : new Invalid("step needs \"value\": 1.." + MAX_STEP_MILLIS + " ms");
      case "speed" ->
          value > 0 && value <= MAX_SPEEDUP
              ? new Sim(SimAction.SPEED, value)
              : new Invalid("speed needs \"value\": a speed-up above 0, at most " + MAX_SPEEDUP);
      default -> new Invalid("unknown simulation command (run, pause, step, speed)");
    };
  }

  private static double number(Map<?, ?> m, String object, String field) {
    return m.get(object) instanceof Map<?, ?> o && o.get(field) instanceof Number n
        ? n.doubleValue()
        : Double.NaN;
  }

  private static double clamp(double v, double max) {
    return Math.max(-max, Math.min(max, v));
  }

  /**
   * Carries out {@code command} with {@code controls}.
   *
   * @return null if done, else why not (no such control here, or the goal was refused)
   */
  static String apply(ControlCommand command, Controls controls) {
    if (command instanceof Invalid i) {
      return i.reason();
    }
    if (command instanceof Sim s) {
      Controls.Simulation sim = controls.simulation();
      if (sim == null) {
        return "there is no simulation to control here";
      }
      switch (s.action()) {
        case RUN -> sim.run();
        case PAUSE -> sim.pause();
        case STEP -> sim.step((long) s.value());
        case SPEED -> sim.setSpeedup(s.value());
      }
      return null;
    }
    Controls.Driver driver = controls.driver();
    if (driver == null) {
      return "no robot can be driven here";
    }
    if (command instanceof Drive d) {
      driver.drive(d.vel(), d.rotVel());
      return null;
    }
    Goal g = (Goal) command;
    return driver.goTo(g.pose(), g.useHeading())
        ? null
        : "no path to " + Math.round(g.pose().x()) + ", " + Math.round(g.pose().y());
  }
}
