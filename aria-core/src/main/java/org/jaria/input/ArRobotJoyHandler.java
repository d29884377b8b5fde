package org.jaria.input;

import java.util.concurrent.atomic.AtomicLong;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.JoystickPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.robot.ArListPos;
import org.jaria.robot.ArPacketHandler;
import org.jaria.robot.ArRobot;

/**
 * The joystick plugged into the robot itself (ARIA's {@code ArRobotJoyHandler}): asks the
 * controller for a stream of JOYSTICKpacs (JOYINFO 2) on every connection and keeps the latest.
 * Axes come as 0..1023 around 512 and are given here as −1..1 with x positive to the right and y
 * positive forward, like {@link ArJoyHandler}; the throttle as 0..1.
 */
public class ArRobotJoyHandler implements AutoCloseable {

  private final ArRobot robot;
  private final ArPacketHandler handler = this::handleJoystickPacket;
  private final Runnable connectCb = this::connected;
  private final AtomicLong packets = new AtomicLong();
  private volatile JoystickPacket last = new JoystickPacket(0, 0, 512, 512, 0);
  private volatile long receivedNanos;

  /** Starts reading the joystick of {@code robot}. */
  public ArRobotJoyHandler(ArRobot robot) {
    this.robot = robot;
    robot.addPacketHandler(handler, ArListPos.LAST);
    robot.addConnectCB(connectCb);
    if (robot.isConnected()) {
      connected();
    }
  }

  private void connected() {
    robot.comInt(ArCommands.JOYINFO, 2);
  }

  private boolean handleJoystickPacket(ArRobotPacket p) {
    if (p.getID() != PacketIds.JOYSTICK) {
      return false;
    }
    JoystickPacket j = JoystickPacket.decode(p);
    if (j != null) {
      last = j;
      receivedNanos = robot.getClock().nanoTime();
      packets.incrementAndGet();
    }
    return true;
  }

  /** Whether the first button (the deadman) is pressed. */
  public boolean getButton1() {
    return last.button1() != 0;
  }

  /** Whether the second button is pressed. */
  public boolean getButton2() {
    return last.button2() != 0;
  }

  /** x (right positive) and y (forward positive) as −1..1, and the throttle as 0..1. */
  public ArJoyHandler.JoyVec3f getDoubles() {
    JoystickPacket j = last;
    return new ArJoyHandler.JoyVec3f(
        (j.x() - 512) / 512.0, (j.y() - 512) / 512.0, j.throttle() / 1024.0);
  }

  /** The last packet (centred and released before one arrives). */
  public JoystickPacket getLastPacket() {
    return last;
  }

  /** Clock time the last packet arrived, ns (0 if none). */
  public long getDataReceivedNanos() {
    return receivedNanos;
  }

  /** JOYSTICKpacs received. */
  public long getPacketsReceived() {
    return packets.get();
  }

  /** Stops reading (the robot keeps streaming until it is told JOYINFO 0 or disconnects). */
  @Override
  public void close() {
    robot.remPacketHandler(handler);
    robot.remConnectCB(connectCb);
  }
}
