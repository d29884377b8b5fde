package org.jaria.net.server.info;

import org.jaria.net.ArNetPacket;
import org.jaria.net.data.CameraInfo;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.TextLimits;
import org.jaria.net.server.Where;

/**
 * The robot's cameras for clients (ArNetworking's {@code ArServerHandlerCameraCollection}), with
 * ArNetworking's names and layouts: {@code "getCameraList"} lists each camera with its requests
 * ({@link CameraInfo}); {@code "cameraListUpdated"} is an empty packet sent to the clients that
 * asked for it whenever the collection changes; {@code "setCameraParams"} and {@code
 * "cameraParamUpdated"} carry camera parameters, which JAria's cameras do not have: a request is
 * answered with the camera's name and the empty name that ends the list of parameters changed.
 */
public final class ArServerHandlerCameraCollection {

  /** The command group of the four data, as ARIA's. */
  public static final String COMMAND_GROUP = "CameraInfo";

  /** Registers the collection's data with {@code server}. */
  public ArServerHandlerCameraCollection(ArServerBase server, ArCameraCollection collection) {
    server.addData(
        "getCameraList",
        "Gets information about the robot's cameras.",
        "none",
        "byte2: numCameras, repeating for numCameras: { string: cameraName, string: cameraType,"
            + " string: displayName, string: displayType, byte2: numCommands, repeating for"
            + " numCommands: {string: command, string: cameraCommandName byte4: requestInterval }"
            + " byte2: numParams, repeating for numParams: {see ArConfigArg format}}",
        COMMAND_GROUP,
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> CameraInfo.writeList(reply, collection.getCameras()));
    server.addData(
        "setCameraParams",
        "Sets the specified camera parameters.",
        "string: cameraName, repeating for each param: { string: paramName, <param value - see"
            + " ArConfigArg format> }, empty paramName terminates list",
        "string: cameraName, repeating for each modified param: { string: paramName, <param value"
            + " - see ArConfigArg format> }, empty paramName terminates list",
        COMMAND_GROUP,
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> {
          // No camera here has parameters: none is changed, whatever was asked.
          String camera = request.hasMore() ? request.bufToStr() : "";
          reply.strToBuf(TextLimits.clip(camera, TextLimits.MAX_NAME)).strToBuf("");
        });
    server.addData(
        "cameraListUpdated",
        "Single packet is sent when the camera collection has been modified.",
        "none",
        "none",
        COMMAND_GROUP,
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> {});
    server.addData(
        "cameraParamUpdated",
        "Packet is sent when the camera parameters have been modified.",
        "none",
        "string: cameraName, repeating for each modified param: { string: paramName, <param value"
            + " - see ArConfigArg format> }, empty paramName terminates list",
        COMMAND_GROUP,
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> {});
    collection.addModifiedCB(
        () -> server.broadcastPacketTcp(new ArNetPacket(), "cameraListUpdated"));
  }
}
