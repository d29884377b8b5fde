package org.jaria.action;

import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.JoystickPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.robot.ArListPos;
import org.jaria.robot.ArPacketHandler;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Drives the robot with the joystick plugged into the robot itself (ARIA's {@code
 * ArActionRobotJoydrive}). On connecting it asks the controller for a continuous stream of
 * JOYSTICKpacs (JOYINFO 2) and reads them as they arrive. The axes run 0..1023 around 512; beyond a
 * third of the way out the action drives: speed = deflection × throttle × the robot's maximum
 * translational velocity, and likewise rotation with the maximum rotational velocity. Pulling
 * against the current motion raises the deceleration threefold.
 *
 * <p>With {@code requireDeadmanPushed} (the default) nothing happens unless the first button is
 * held. With the stick centred it stops the robot once, then (if no deadman is required) lets
 * lower-priority actions drive.
 */
public class ArActionRobotJoydrive extends ArAction {

  private static final Logger log = LoggerFactory.getLogger(ArActionRobotJoydrive.class);

  private final ArActionDesired desired = new ArActionDesired();
  private final Runnable connectCb = this::connectCallback;
  private final ArPacketHandler packetHandler = this::handleJoystickPacket;
  private volatile boolean requireDeadmanPushed;
  private volatile JoystickPacket last = new JoystickPacket(0, 0, 512, 512, 0);
  private final java.util.concurrent.atomic.AtomicLong packetsReceived =
      new java.util.concurrent.atomic.AtomicLong();
  private boolean deadZoneLast;

  /** "robotJoyDrive", requiring the deadman button. */
  public ArActionRobotJoydrive() {
    this("robotJoyDrive", true);
  }

  /**
   * A robot-joystick action.
   *
   * @param name the action's name
   * @param requireDeadmanPushed drive only while the first button is held
   */
  public ArActionRobotJoydrive(String name, boolean requireDeadmanPushed) {
    super(
        name,
        "This action reads the joystick on the robot and sets the translational and rotational"
            + " velocities based on this.");
    this.requireDeadmanPushed = requireDeadmanPushed;
  }

  @Override
  public void setRobot(ArRobot r) {
    ArRobot previous = getRobot();
    super.setRobot(r);
    if (previous == r) {
      // Added again (a new priority): already listening.
      return;
    }
    if (previous != null) {
      previous.remConnectCB(connectCb);
      previous.remPacketHandler(packetHandler);
    }
    r.addConnectCB(connectCb);
    r.addPacketHandler(packetHandler, ArListPos.LAST);
    if (r.isConnected()) {
      connectCallback();
    }
  }

  private void connectCallback() {
    ArRobot r = getRobot();
    if (r != null) {
      r.comInt(ArCommands.JOYINFO, 2);
    }
  }

  /** Takes JOYSTICKpacs; returns whether the packet was one. */
  boolean handleJoystickPacket(ArRobotPacket packet) {
    if (packet.getID() != PacketIds.JOYSTICK) {
      return false;
    }
    JoystickPacket j = JoystickPacket.decode(packet);
    if (j == null) {
      log.debug("short JOYSTICKpac ignored");
      return true;
    }
    last = j;
    packetsReceived.incrementAndGet();
    return true;
  }

  /** The last joystick packet received (centred and released before any arrives). */
  public JoystickPacket getLastJoystickPacket() {
    return last;
  }

  /** How many JOYSTICKpacs have arrived. */
  public long getPacketsReceived() {
    return packetsReceived.get();
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    JoystickPacket j = last;
    desired.reset();
    if (requireDeadmanPushed && j.button1() == 0) {
      deadZoneLast = false;
      return null;
    }
    double ratioRot = -(j.x() - 512) / 512.0;
    double ratioTrans = (j.y() - 512) / 512.0;
    double ratioThrottle = j.throttle() / 1024.0;
    boolean doTrans = Math.abs(ratioTrans) > .33;
    boolean doRot = Math.abs(ratioRot) > .33;
    if (!doTrans && !doRot) {
      if (deadZoneLast && !requireDeadmanPushed) {
        return null;
      }
      desired.setVel(0);
      desired.setDeltaHeading(0);
      deadZoneLast = true;
      return desired;
    }
    deadZoneLast = false;
    double vel = robot.getVel();
    if (doTrans && ((vel > 0 && ratioTrans < -0.5) || (vel < 0 && ratioTrans > 0.5))) {
      desired.setTransDecel(robot.getTransDecel() * 3);
    }
    double rotVel = robot.getRotVel();
    if (doRot && ((rotVel > 0 && ratioRot < -0.5) || (rotVel < 0 && ratioRot > 0.5))) {
      desired.setRotDecel(robot.getRotDecel() * 3);
    }
    desired.setVel(doTrans ? ratioTrans * ratioThrottle * robot.getTransVelMax() : 0);
    desired.setRotVel(doRot ? ratioRot * ratioThrottle * robot.getRotVelMax() : 0);
    return desired;
  }
}
