package org.jaria.net.server.info;

import org.jaria.net.ArNetPacket;
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
  private final PublishedValue numbers = new PublishedValue();
  private final PublishedValue strings = new PublishedValue();

  /** The "updateNumbers" value: the update's numbers only. */
  private record Numbers(RobotUpdate u) implements org.jaria.net.NetEncodable {
    @Override
    public void write(ArNetPacket out) {
      u.writeNumbers(out);
    }
  }

  /** The "updateStrings" value: status, mode and extended status. */
  private record Strings(String status, String mode, String extended)
      implements org.jaria.net.NetEncodable {
    @Override
    public void write(ArNetPacket out) {
      out.strToBuf(status).strToBuf(mode).strToBuf(extended);
    }
  }

  /** Registers {@code "update"} and {@code "physicalInfo"} with {@code server}. */
  public ArServerInfoRobot(ArServerBase server, ArRobot robot) {
    this.robot = robot;
    this.modes = ArServerModes.of(server);
    // Names, descriptions and layouts are ArNetworking's, so MobileEyes and ARIA's clients read
    // them; "update" is encoded once per robot cycle for every client that asked for it.
    server.addPublishedData(
        "update",
        "gets an update about the important robot status (you should request this at an"
            + " interval)",
        "string: status; string: mode; byte2: 10 * battery; byte4: x; byte4: y; byte2: th;"
            + " byte2: transVel; byte2: rotVel, byte2: latVel, byte: temperature (deg c, -128"
            + " means unknown)",
        "RobotInfo",
        update);
    server.addPublishedData(
        "updateNumbers",
        "gets an update about the important robot status (you should request this at an"
            + " interval)",
        "byte2: 10 * battery; byte4: x; byte4: y; byte2: th; byte2: transVel; byte2: rotVel,"
            + " byte2: latVel, byte: temperature (deg c, -128 means unknown)",
        "RobotInfo",
        numbers);
    server.addPublishedData(
        "updateStrings",
        "gets an update about the important robot status (you should ask for this at -1"
            + " interval since it is broadcast when the strings change)",
        "string: status; string: mode; string: extended status (this has newlines)",
        "RobotInfo",
        strings);
    server.addData(
        "batteryInfo",
        "gets the low battery voltage and shutdown voltage (you only need to request this once)",
        "none",
        "double: low battery voltage, double: shutdown battery voltage: ubyte:"
            + " voltageIsStateOfCharge",
        "RobotInfo",
        Where.WORKER,
        (client, request, reply) -> reply.doubleToBuf(11.5).doubleToBuf(11).uByteToBuf(0));
    server.addData(
        "physicalInfo",
        "gets the information about the physical robot (you only need to request this once)",
        "none",
        "string: robotType; string: robotSubType; byte2: robotWidth; byte2: robotLengthFront;"
            + " byte2: robotLengthRear; byte: 0 means no lateral control, 1 means lateral control",
        "RobotInfo",
        Where.WORKER,
        (client, request, reply) -> physicalInfo().write(reply));
    server.addCycleTask(CYCLE_TASK, this::snapshot);
    snapshot();
  }

  /** Cycle thread: one immutable record from the robot's published status. */
  private void snapshot() {
    RobotStatus s = robot.getStatus();
    RobotUpdate u =
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
            robot.getCounter());
    update.publish(u);
    numbers.publish(new Numbers(u));
    strings.publishIfChanged(new Strings(u.status(), u.mode(), u.status()));
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
