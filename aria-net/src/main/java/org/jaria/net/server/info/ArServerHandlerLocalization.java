package org.jaria.net.server.info;

import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.net.protocol.NetError;
import org.jaria.net.provider.LocalizationInfo;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.NetRequestException;
import org.jaria.net.server.NumericArgs;
import org.jaria.net.server.Where;
import org.jaria.robot.ArRobot;

/**
 * Lets an operator relocalize the robot (ArNetworking's {@code ArServerHandlerLocalization}):
 * {@code "localizeToPose"} hands the pose to the {@link LocalizationInfo}; without a localizer it
 * simply declares the robot to be there ({@link ArRobot#moveTo}, on the cycle).
 */
public final class ArServerHandlerLocalization {

  private volatile ArMap map;

  /**
   * Registers {@code "localizeToPose"} with {@code server}.
   *
   * @param loc the localizer, or null to move the robot's pose instead
   */
  public ArServerHandlerLocalization(ArServerBase server, ArRobot robot, LocalizationInfo loc) {
    this(server, robot, loc, null);
  }

  /**
   * Registers {@code "localizeToPose"}, refusing poses outside {@code map} (null: any finite pose).
   */
  public ArServerHandlerLocalization(
      ArServerBase server, ArRobot robot, LocalizationInfo loc, ArMap map) {
    this.map = map;
    server.addData(
        "localizeToPose",
        "Initialize localization at the given point in the map",
        "byte4: x; byte4: y; byte4: th",
        "none",
        "Localization",
        Where.WORKER,
        (client, request, reply) -> {
          // ArNetworking's layout (RemoteRequestAPI): three 4-byte integers, mm and degrees.
          ArPose pose =
              NumericArgs.pose(
                  request.bufToByte4(), request.bufToByte4(), request.bufToByte4(), this.map);
          if (loc != null) {
            if (!loc.localizeToPose(pose)) {
              throw new NetRequestException(
                  NetError.FAILED, "the localization did not accept the pose " + pose);
            }
          } else if (!server.runOnCycle(() -> robot.moveTo(pose))) {
            throw new NetRequestException(NetError.BUSY, "the robot's command queue is full");
          }
        });
  }

  /** Checks poses against another map from now on (after a map change). */
  public void setMap(ArMap m) {
    map = m;
  }
}
