package org.jaria.net.server.info;

import org.jaria.net.data.PhysicalInfo;
import org.jaria.net.data.RobotUpdate;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.PublishedValue;
import org.jaria.net.server.Where;
import org.jaria.net.server.modes.ArServerModes;
import org.jaria.robot.ArRobot;
import org.jaria.robot.RobotStatus;

/**
 * The robot's state for clients (ArNetworking's {@code ArServerInfoRobot}). Every robot cycle a
 * task copies the robot's latest status and the active mode into one immutable {@link RobotUpdate}
 * — a single allocation, nothing else — which the server publishes as {@code "update"}; {@code
 * "physicalInfo"} answers what the robot is and how big.
 */
public final class ArServerInfoRobot {

  /** Name of the cycle task that takes the snapshot. */
  public static final String CYCLE_TASK = "ArServerInfoRobot";

  private final ArRobot robot;
  private final ArServerModes modes;
  private final PublishedValue update = new PublishedValue();

  /** Registers {@code "update"} and {@code "physicalInfo"} with {@code server}. */
  public ArServerInfoRobot(ArServerBase server, ArRobot robot) {
    this.robot = robot;
    this.modes = ArServerModes.of(server);
    server.addPublishedData(
        "update",
        "the robot's state: subscribe at the rate you want to draw it",
        "RobotUpdate [mode, status, battery V, x, y, th, vel, rotVel, leftVel, rightVel,"
            + " motorsEnabled, leftStalled, rightStalled, eStop, chargeState, counter]",
        "RobotInfo",
        update);
    server.addData(
        "physicalInfo",
        "what the robot is and its size (ask once)",
        "none",
        "PhysicalInfo [name, type, subType, width, lengthFront, lengthRear, radius, numSonar,"
            + " maxTransVel, maxRotVel]",
        "RobotInfo",
        Where.WORKER,
        (client, request, reply) -> physicalInfo().write(reply));
    server.addCycleTask(CYCLE_TASK, this::snapshot);
    snapshot();
  }

  /** Cycle thread: one immutable record from the robot's published status. */
  private void snapshot() {
    RobotStatus s = robot.getStatus();
    update.publish(
        new RobotUpdate(
            modes.getMode(),
            modes.getStatus(),
            s.batteryVoltage(),
            s.pose().getX(),
            s.pose().getY(),
            s.pose().getTh(),
            s.vel(),
            s.rotVel(),
            s.leftVel(),
            s.rightVel(),
            robot.areMotorsEnabled(),
            robot.isLeftMotorStalled(),
            robot.isRightMotorStalled(),
            robot.isEStopPressed(),
            s.chargeState(),
            robot.getCounter()));
  }

  /** What the robot is, from its parameters. */
  public PhysicalInfo physicalInfo() {
    return new PhysicalInfo(
        robot.getName(),
        robot.getRobotType(),
        robot.getRobotSubType(),
        robot.getRobotWidth(),
        robot.getRobotLengthFront(),
        robot.getRobotLengthRear(),
        robot.getRobotRadius(),
        robot.getNumSonar(),
        robot.getAbsoluteMaxTransVel(),
        robot.getAbsoluteMaxRotVel());
  }
}
