package org.jaria.net.server.modes;

import java.time.Duration;
import java.util.Locale;
import org.jaria.action.ArActionDeceleratingLimiter;
import org.jaria.action.ArActionGroup;
import org.jaria.action.ArActionRatioInput;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.CallPolicy;
import org.jaria.net.server.NumericArgs;
import org.jaria.net.server.Where;
import org.jaria.robot.ArRobot;

/**
 * Teleoperation from a client, like a joystick (ArNetworking's {@code ArServerModeRatioDrive}): the
 * client sends ratios — translation and rotation −100..100, throttle 0..100 — several times a
 * second, and an {@link ArActionRatioInput} turns them into speeds, with decelerating limiters in
 * front and behind that brake before obstacles ("safe drive", the default).
 *
 * <p><b>Deadman.</b> If no command arrives for the timeout (default 2 s, on the robot's clock)
 * while the ratios ask for motion, the ratios are set to zero and the robot stops: a client that
 * crashes or loses its connection cannot leave the robot driving. Client requests: {@code
 * "ratioDrive"}, {@code "setSafeDrive"}, {@code "getSafeDrive"}.
 */
public class ArServerModeRatioDrive extends ArServerMode {

  private final ArActionGroup group;
  private final ArActionRatioInput input = new ArActionRatioInput();
  private final ArActionDeceleratingLimiter forward =
      new ArActionDeceleratingLimiter(
          "DeceleratingLimiterForward", ArActionDeceleratingLimiter.LimiterType.FORWARDS);
  private final ArActionDeceleratingLimiter backward =
      new ArActionDeceleratingLimiter(
          "DeceleratingLimiterBackward", ArActionDeceleratingLimiter.LimiterType.BACKWARDS);
  private volatile long timeoutNanos = Duration.ofSeconds(2).toNanos();
  private volatile boolean safe = true;
  // Cycle thread only.
  private long lastCommandNanos;
  private boolean wantToMove;
  private boolean timedOut;

  /** Registers the teleoperation requests with {@code server}. */
  public ArServerModeRatioDrive(ArServerBase server, ArRobot robot) {
    super(server, robot, "Drive");
    group = new ArActionGroup(robot);
    withRobotLocked(
        robot,
        () -> {
          group.addAction(input, 50);
          group.addAction(forward, 40);
          group.addAction(backward, 39);
          group.deactivate();
        });
    server.addData(
        "ratioDrive",
        "drives the robot as with a joystick; send it several times a second",
        "double: transRatio (0,100); double: rotRatio (0,100); double: throttleRatio (0,100);"
            + " [double: lateralRatio (0,100)] ",
        "none",
        "Movement",
        Where.CYCLE,
        (client, request, reply) -> {
          double trans = NumericArgs.within(request.bufToDouble(), -100, 100, "transRatio");
          double rot = NumericArgs.within(request.bufToDouble(), -100, 100, "rotRatio");
          double throttle = NumericArgs.within(request.bufToDouble(), 0, 100, "throttleRatio");
          if (request.hasMore()) {
            NumericArgs.within(request.bufToDouble(), -100, 100, "lateralRatio");
          }
          ratioDrive(trans, rot, throttle);
        });
    // ARIA's clients send ratioDrive at every turn of their loop (clientDemo: about 900 a second):
    // only the newest matters, so a newer one replaces one still waiting instead of piling up.
    server.setCallPolicy("ratioDrive", CallPolicy.LATEST_WINS);
    server.addData(
        "setSafeDrive",
        "whether the limiters brake before obstacles (false is UNSAFE)",
        "byte: 1 == drive safely, 0 == drive unsafely",
        "none",
        "UnsafeMovement",
        Where.CYCLE,
        (client, request, reply) -> setSafeDriving(request.bufToBool()));
    server.addData(
        "getSafeDrive",
        "whether teleoperation brakes before obstacles",
        "none",
        "byte: 1 == driving safely, 0 == driving unsafely",
        "Movement",
        Where.WORKER,
        (client, request, reply) -> reply.boolToBuf(safe));
  }

  /** The teleoperation actions (to add, say, an ArActionLost). */
  public ArActionGroup getActionGroup() {
    return group;
  }

  /** The ratio input action. */
  public ArActionRatioInput getRatioAction() {
    return input;
  }

  /** Sets the deadman timeout (zero: never stop for lack of commands). */
  public void setTimeout(Duration d) {
    timeoutNanos = d.toNanos();
  }

  /** The deadman timeout. */
  public Duration getTimeout() {
    return Duration.ofNanos(timeoutNanos);
  }

  /** Whether the limiters are used. */
  public boolean getSafeDriving() {
    return safe;
  }

  /**
   * Drives with ratios (cycle thread), activating the mode if needed.
   *
   * @param transRatio −100 (full backwards) .. 100 (full forwards)
   * @param rotRatio −100 (full right) .. 100 (full left)
   * @param throttleRatio 0 .. 100
   */
  public void ratioDrive(double transRatio, double rotRatio, double throttleRatio) {
    if (!isActive()) {
      activate();
    }
    input.setRatios(transRatio, rotRatio, throttleRatio);
    wantToMove = throttleRatio > 1e-6 && (Math.abs(transRatio) > 1e-6 || Math.abs(rotRatio) > 1e-6);
    lastCommandNanos = robot.getClock().nanoTime();
    timedOut = false;
  }

  /** Turns the limiters on (safe) or off (cycle thread). */
  public void setSafeDriving(boolean on) {
    if (on == safe) {
      return;
    }
    safe = on;
    if (isActive()) {
      applyActions();
    }
  }

  private void applyActions() {
    if (safe) {
      group.activateExclusive();
      setMode("Drive");
    } else {
      robot.deactivateActions();
      input.activate();
      setMode("UNSAFE Drive");
    }
  }

  @Override
  protected void onActivate() {
    robot.clearDirectMotion();
    robot.enableMotors();
    applyActions();
    input.setRatios(0, 0, 0);
    wantToMove = false;
    lastCommandNanos = robot.getClock().nanoTime();
    setStatus("Stopped");
  }

  @Override
  protected void onDeactivate() {
    input.setRatios(0, 0, 0);
    wantToMove = false;
    group.deactivate();
  }

  @Override
  protected void userTask() {
    long timeout = timeoutNanos;
    if (wantToMove && timeout > 0 && robot.getClock().nanoTime() - lastCommandNanos >= timeout) {
      input.setRatios(0, 0, 0);
      wantToMove = false;
      timedOut = true;
    }
    if (timedOut) {
      setStatus(String.format(Locale.ROOT, "Stopped: no drive command for %.1f s", timeout / 1e9));
    } else {
      setStatus(wantToMove ? "Driving" : "Stopped");
    }
  }
}
