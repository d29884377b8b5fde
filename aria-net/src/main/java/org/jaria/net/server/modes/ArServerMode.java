package org.jaria.net.server.modes;

import java.util.Objects;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.TextLimits;
import org.jaria.robot.ArRobot;

/**
 * A way of driving the robot that a client can switch to (ArNetworking's {@code ArServerMode}):
 * stop, teleoperation, wander, goto. Exactly one mode of a server is active; activating one
 * deactivates the previous. Modes own their actions: a mode activates its action group when it
 * becomes active and deactivates it when it stops, so the modes never fight.
 *
 * <p>Activation, deactivation and {@link #userTask()} all run on the robot's cycle thread: modes
 * register their client requests with {@link org.jaria.net.server.Where#CYCLE}. The mode and status
 * strings may be read from any thread.
 */
public abstract class ArServerMode {

  protected final ArServerBase server;
  protected final ArRobot robot;
  private final String name;
  private final ArServerModes modes;
  private volatile String mode;
  private volatile String status = "";

  /**
   * A mode of {@code server} driving {@code robot}.
   *
   * @param name the mode's name (also its initial mode string)
   */
  protected ArServerMode(ArServerBase server, ArRobot robot, String name) {
    this.server = Objects.requireNonNull(server, "server");
    this.robot = Objects.requireNonNull(robot, "a server mode needs the robot it drives");
    this.name = name;
    this.mode = name;
    this.modes = ArServerModes.of(server);
    modes.add(this);
  }

  /** The mode's name. */
  public String getName() {
    return name;
  }

  /** What the mode is, for people ("Stop", "Drive", "UNSAFE Drive" ...). */
  public String getMode() {
    return mode;
  }

  /** What it is doing, for people ("Stopped", "Going to goal A" ...). */
  public String getStatus() {
    return status;
  }

  /** Sets the mode string (cut to {@link TextLimits#MAX_MESSAGE}: every client receives it). */
  protected void setMode(String m) {
    mode = TextLimits.clip(m, TextLimits.MAX_MESSAGE);
  }

  /**
   * Sets the status string (cut to {@link TextLimits#MAX_MESSAGE}: it goes to every client in each
   * {@code update}, so a name a client gave cannot make it grow).
   */
  protected void setStatus(String s) {
    status = TextLimits.clip(s, TextLimits.MAX_MESSAGE);
  }

  /** Whether this is the active mode. */
  public boolean isActive() {
    return modes.getActiveMode() == this;
  }

  /** Makes this the mode that takes over whenever no mode is active (usually stop). */
  public void addAsDefaultMode() {
    modes.setDefault(this);
  }

  /** Makes this the active mode. Call on the robot's cycle (from a CYCLE handler). */
  public void activate() {
    modes.activate(this);
  }

  /** Stops this mode (the default mode takes over). Call on the robot's cycle. */
  public void deactivate() {
    modes.deactivate(this);
  }

  final void doActivate() {
    onActivate();
  }

  final void doDeactivate() {
    onDeactivate();
  }

  /** Switches the mode's actions on (cycle thread). */
  protected abstract void onActivate();

  /** Switches the mode's actions off (cycle thread). */
  protected abstract void onDeactivate();

  /** Runs every cycle while the mode is active (cycle thread): update status, timeouts. */
  protected void userTask() {}

  /**
   * Makes the robot's construction-time actions quiet: adding actions to a robot makes them active,
   * so a mode deactivates its group right after building it, under the robot's lock so no cycle
   * runs them in between.
   */
  protected static void withRobotLocked(ArRobot robot, Runnable r) {
    robot.lock();
    try {
      r.run();
    } finally {
      robot.unlock();
    }
  }

  @Override
  public String toString() {
    return "ArServerMode[" + name + (isActive() ? ", active]" : "]");
  }
}
