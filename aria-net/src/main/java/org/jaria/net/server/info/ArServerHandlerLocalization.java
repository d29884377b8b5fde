package org.jaria.net.server.info;

import org.jaria.geom.ArPose;
import org.jaria.net.protocol.NetError;
import org.jaria.net.provider.LocalizationInfo;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.NetRequestException;
import org.jaria.net.server.Where;
import org.jaria.robot.ArRobot;

/**
 * Lets an operator relocalize the robot (ArNetworking's {@code ArServerHandlerLocalization}):
 * {@code "localizeToPose"} hands the pose to the {@link LocalizationInfo}; without a localizer it
 * simply declares the robot to be there ({@link ArRobot#moveTo}, on the cycle).
 */
public final class ArServerHandlerLocalization {

  /**
   * Registers {@code "localizeToPose"} with {@code server}.
   *
   * @param loc the localizer, or null to move the robot's pose instead
   */
  public ArServerHandlerLocalization(ArServerBase server, ArRobot robot, LocalizationInfo loc) {
    server.addData(
        "localizeToPose",
        "relocalizes the robot at a pose",
        "double x (mm), double y (mm), double th (deg)",
        "bool accepted",
        "Localization",
        Where.WORKER,
        (client, request, reply) -> {
          ArPose pose =
              new ArPose(request.bufToDouble(), request.bufToDouble(), request.bufToDouble());
          if (loc != null) {
            reply.boolToBuf(loc.localizeToPose(pose));
          } else if (server.runOnCycle(() -> robot.moveTo(pose))) {
            reply.boolToBuf(true);
          } else {
            throw new NetRequestException(NetError.BUSY, "the robot's command queue is full");
          }
        });
  }
}
