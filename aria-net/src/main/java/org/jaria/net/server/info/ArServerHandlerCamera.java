package org.jaria.net.server.info;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.net.ArNetPacket;
import org.jaria.net.protocol.NetError;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.NetRequestException;
import org.jaria.net.server.RequestHandler;
import org.jaria.net.server.TextLimits;
import org.jaria.net.server.Where;
import org.jaria.ptz.ArPTZ;
import org.jaria.robot.ArRobot;

/**
 * Lets clients point the robot's pan-tilt-zoom camera (ArNetworking's {@code
 * ArServerHandlerCamera}), with ArNetworking's requests and layouts, so ARIA's {@code
 * ptzCameraClientExample} and MobileEyes pan and tilt it. The requests are named after the camera
 * ("getCameraInfoCam1"; no suffix for a camera without a name) and listed in an {@link
 * ArCameraCollection} when one is given:
 *
 * <ul>
 *   <li>{@code getCameraData}: pan, tilt and zoom (percent of the range), each a {@code byte2} of
 *       the value × 100; meant to be requested every 100 ms;
 *   <li>{@code getCameraInfo}: the pan and tilt ranges, the zoom range (0 to 100 percent), each ×
 *       100, then a {@code byte}: whether it zooms;
 *   <li>{@code setCameraAbs}, {@code setCameraRel}: pan, tilt and (optionally) zoom as {@code
 *       byte2} × 100, absolute or relative (a missing zoom reads as 0, as in ARIA);
 *   <li>{@code getCameraModeList}, {@code setCameraMode}, {@code cameraModeUpdated}: the modes
 *       "Position" and "LookAtPoint" (then two {@code byte4}, x and y on the map: the camera keeps
 *       facing that point as the robot moves);
 *   <li>{@code resetCamera}: back to 0, 0, no zoom;
 *   <li>ArNetworking's older integer requests, never suffixed: {@code cameraUpdate}, {@code
 *       cameraInfo}, {@code camera} (relative) and {@code cameraAbs}, in whole degrees and {@code
 *       byte}s.
 * </ul>
 *
 * <p>Pointing by a percentage of the picture ({@code setCameraPct}, {@code cameraPct}) needs the
 * camera's field of view, which {@link ArPTZ} does not give: {@code setCameraPct} is not offered
 * and {@code cameraPct} is refused, as ARIA does for such a camera. Commands run on the robot's
 * cycle; the camera's own class paces what it sends.
 *
 * <p>Angles pass through unchanged, in ARIA's signs on both sides: a client's pan to the right is
 * positive, and so is {@link ArPTZ}'s.
 */
public final class ArServerHandlerCamera {

  /** Command group of the requests that move the camera. */
  public static final String CONTROL_COMMAND_GROUP = "CameraControl";

  /** Command group of the requests that only read. */
  public static final String INFO_COMMAND_GROUP = "CameraInfo";

  /** The "double" values travel as {@code byte2} of the value times this. */
  public static final double DOUBLE_FACTOR = 100;

  private static final String NO_ARGS = "None";

  /** The camera's modes, in ARIA's order (LookAtGoal, which ARNL drives, is not offered). */
  private static final List<String> MODES = List.of("Position", "LookAtPoint");

  private final String cameraName;
  private final ArServerBase server;
  private final ArRobot robot;
  private final ArPTZ camera;

  /** ArCameraCommands name → this server's request, in the order ARIA registers them. */
  private final Map<String, String> requests = new LinkedHashMap<>();

  private volatile ArPose lookAt;

  /** A handler for a camera without a name (ARIA's first constructor). */
  public ArServerHandlerCamera(ArServerBase server, ArRobot robot, ArPTZ camera) {
    this("", server, robot, camera, null);
  }

  /**
   * A handler for camera {@code cameraName}, listed in {@code collection} (which must already have
   * the camera; null for none).
   */
  public ArServerHandlerCamera(
      String cameraName,
      ArServerBase server,
      ArRobot robot,
      ArPTZ camera,
      ArCameraCollection collection) {
    this.cameraName = Objects.requireNonNullElse(cameraName, "");
    this.server = Objects.requireNonNull(server, "server");
    this.robot = robot;
    this.camera = Objects.requireNonNull(camera, "a camera handler needs the camera it points");
    addAll();
    if (robot != null) {
      server.addCycleTask("ArServerHandlerCamera" + this.cameraName, this::followPoint);
    }
    if (collection != null && !this.cameraName.isEmpty() && collection.exists(this.cameraName)) {
      for (Map.Entry<String, String> e : requests.entrySet()) {
        int interval = e.getKey().equals("getCameraData") ? 100 : -1;
        collection.addCameraCommand(this.cameraName, e.getKey(), e.getValue(), interval);
      }
    }
  }

  /** The camera's name ("" for none). */
  public String getCameraName() {
    return cameraName;
  }

  private void addAll() {
    add(
        "getCameraData",
        true,
        "Get \"double\" information about camera position. (factor == 100)",
        NO_ARGS,
        "byte2: pan * factor, byte2: tilt * factor, byte2: zoomPercent * factor (optional)",
        (c, q, r) -> {
          doubleToBuf(r, camera.getPan());
          doubleToBuf(r, camera.getTilt());
          doubleToBuf(r, zoomRatio() * 100);
        });
    add(
        "getCameraInfo",
        true,
        "Get (\"double\") information about the camera's pan, tilt, and (optional) zoom ranges."
            + " (factor == 100)",
        NO_ARGS,
        "byte2: minPan * factor, byte2: maxPan * factor byte2: minTilt * factor, byte2: maxTilt *"
            + " factor, byte2: minZoom * factor, byte2: maxZoom * factor, byte: isZoomAvailable",
        (c, q, r) -> {
          doubleToBuf(r, camera.getMaxNegPan());
          doubleToBuf(r, camera.getMaxPosPan());
          doubleToBuf(r, camera.getMaxNegTilt());
          doubleToBuf(r, camera.getMaxPosTilt());
          doubleToBuf(r, 0);
          doubleToBuf(r, 100);
          r.boolToBuf(camera.canZoom());
        });
    add(
        "setCameraAbs",
        false,
        "Sends absolute (\"double\") pan, tilt, and zoom (optional) commands to the camera."
            + " (factor == 100)",
        NO_ARGS,
        "byte2: pan * factor, byte2: tilt * factor, byte2: zoom * factor (optional)",
        (c, q, r) -> setCameraAbs(bufToDouble(q), bufToDouble(q), bufToDouble(q)));
    add(
        "setCameraRel",
        false,
        "Sends (\"double\") pan, tilt, and zoom (optional) commands to the camera, relative to its"
            + " current position. (factor == 100)",
        NO_ARGS,
        "byte2: relPan * factor, byte2: relTilt * factor, byte2: relZoom * factor (optional)",
        (c, q, r) -> setCameraRel(bufToDouble(q), bufToDouble(q), bufToDouble(q)));
    add(
        "getCameraModeList",
        true,
        "Gets the list of modes this camera supports",
        NO_ARGS,
        "ubyte2: numModes; <repeating numModes times> string: modeName",
        (c, q, r) -> {
          r.uByte2ToBuf(MODES.size());
          for (String m : MODES) {
            r.strToBuf(m);
          }
        });
    add(
        "cameraModeUpdated",
        true,
        "Sent whenever the camera mode is updated",
        NO_ARGS,
        "string: modeName; <other data depends on mode>",
        (c, q, r) -> writeMode(r));
    add(
        "setCameraMode",
        false,
        "Sets the mode of the camera",
        "string: modeName; <other data depends on mode>",
        NO_ARGS,
        (c, q, r) -> setMode(q));
    add(
        "resetCamera",
        false,
        "Resets the camera to 0 0 0 and may reinitialize it (depending on camera)",
        NO_ARGS,
        NO_ARGS,
        (c, q, r) -> {
          camera.reset();
          modePosition();
        });
    // ArNetworking's older integer requests, kept for its older clients; never suffixed.
    addOld(
        "getCameraDataInt",
        "cameraUpdate",
        true,
        "Get (integer) information about camera position",
        "byte2: pan, byte2: tilt, byte2: zoom (optional)",
        (c, q, r) ->
            r.byte2ToBuf((int) Math.round(camera.getPan()))
                .byte2ToBuf((int) Math.round(camera.getTilt()))
                .byte2ToBuf((int) Math.round(zoomRatio() * 100)));
    addOld(
        "getCameraInfoInt",
        "cameraInfo",
        true,
        "Get (integer) information about the camera's pan, tilt, and (optional) zoom ranges",
        "byte2: minPan, byte2: maxPan byte2: minTilt, byte2: maxTilt, byte2: minZoom, byte2:"
            + " maxZoom, byte: isZoomAvailable",
        (c, q, r) ->
            r.byte2ToBuf((int) Math.round(camera.getMaxNegPan()))
                .byte2ToBuf((int) Math.round(camera.getMaxPosPan()))
                .byte2ToBuf((int) Math.round(camera.getMaxNegTilt()))
                .byte2ToBuf((int) Math.round(camera.getMaxPosTilt()))
                .byte2ToBuf(0)
                .byte2ToBuf(100)
                .boolToBuf(camera.canZoom()));
    addOld(
        "setCameraRelInt",
        "camera",
        false,
        "Sends (integer) pan, tilt, and zoom (optional) commands to the camera, relative to its"
            + " current position",
        "byte: relPan, byte: relTilt, byte: relZoom (optional)",
        (c, q, r) -> setCameraRel(bufToByte(q), bufToByte(q), bufToByte(q)));
    addOld(
        "setCameraAbsInt",
        "cameraAbs",
        false,
        "Sends absolute (integer) pan, tilt, and zoom (optional) commands to the camera",
        "byte: pan, byte: tilt, byte: zoom (optional)",
        (c, q, r) -> setCameraAbs(bufToByte(q), bufToByte(q), bufToByte(q)));
    addOld(
        "setCameraPctInt",
        "cameraPct",
        false,
        "Sends (integer) pan, tilt commands to the camera, as percent of visible frame",
        "byte: pan, byte: tilt, byte: zoom (optional)",
        (c, q, r) -> {
          throw new NetRequestException(
              NetError.UNAVAILABLE,
              "this camera does not know its field of view: use cameraAbs or camera instead");
        });
  }

  /** Registers {@code command}, suffixed with the camera's name. */
  private void add(
      String command,
      boolean info,
      String description,
      String args,
      String returns,
      RequestHandler handler) {
    register(command, command + cameraName, info, description, args, returns, handler);
  }

  /** Registers an older request under its own, unsuffixed name (skipped if already taken). */
  private void addOld(
      String command,
      String name,
      boolean info,
      String description,
      String returns,
      RequestHandler handler) {
    if (!server.dataExists(name)) {
      register(command, name, info, description, NO_ARGS, returns, handler);
    }
  }

  private void register(
      String command,
      String name,
      boolean info,
      String description,
      String args,
      String returns,
      RequestHandler handler) {
    server.addData(
        name,
        description,
        args,
        returns,
        info ? INFO_COMMAND_GROUP : CONTROL_COMMAND_GROUP,
        "RETURN_SINGLE",
        info ? Where.WORKER : Where.CYCLE,
        handler);
    requests.put(command, name);
  }

  /** Points the camera at absolute angles and a zoom in percent of its range (0..100). */
  public void setCameraAbs(double pan, double tilt, double zoomPercent) {
    double z = Math.max(0, Math.min(100, zoomPercent));
    modePosition();
    camera.panTilt(pan, tilt);
    camera.zoom((int) Math.round(camera.getMinZoom() + z / 100 * zoomRange()));
  }

  /**
   * Moves the camera by angles and a zoom change in percent, as ARIA does: the angles shrink as the
   * camera zooms in, so a click moves the picture by about the same amount at any zoom.
   */
  public void setCameraRel(double pan, double tilt, double zoomPercent) {
    double inv = zoomRange() == 0 ? 1 : Math.max(0.01, Math.min(1, 1 - zoomRatio()));
    double p = pan > 0 ? Math.ceil(pan * inv) : Math.floor(pan * inv);
    double t = tilt > 0 ? Math.ceil(tilt * inv) : Math.floor(tilt * inv);
    if (zoomPercent != 0) {
      double pct = zoomRatio() * 100 + zoomPercent;
      camera.zoom((int) Math.round(camera.getMinZoom() + pct / 100 * zoomRange()));
    }
    if (p != 0 || t != 0) {
      modePosition();
      camera.panTilt(camera.getPan() + p, camera.getTilt() + t);
    }
  }

  /** The mode's name: "Position", or "LookAtPoint" while the camera faces a point. */
  public String getMode() {
    return lookAt == null ? MODES.get(0) : MODES.get(1);
  }

  private void setMode(ArNetPacket q) throws NetRequestException {
    String name = q.bufToStr();
    if (name.equalsIgnoreCase("Position")) {
      modePosition();
    } else if (name.equalsIgnoreCase("LookAtPoint")) {
      if (robot == null) {
        throw new NetRequestException(
            NetError.UNAVAILABLE, "without the robot's pose the camera cannot face a point");
      }
      ArPose p = new ArPose(q.bufToByte4(), q.bufToByte4());
      ArPose old = lookAt;
      if (old == null || old.findDistanceTo(p) > 1) {
        lookAt = p;
        camera.zoom(camera.getMinZoom());
        broadcastMode();
      }
    } else {
      throw new NetRequestException(
          NetError.BAD_ARGUMENTS,
          "no camera mode '"
              + TextLimits.clip(name, TextLimits.MAX_NAME)
              + "'; see getCameraModeList"
              + cameraName);
    }
  }

  private void modePosition() {
    if (lookAt != null) {
      lookAt = null;
      broadcastMode();
    }
  }

  private void writeMode(ArNetPacket p) {
    ArPose at = lookAt;
    p.strToBuf(at == null ? MODES.get(0) : MODES.get(1));
    if (at != null) {
      p.byte4ToBuf((int) Math.round(at.x())).byte4ToBuf((int) Math.round(at.y()));
    }
  }

  private void broadcastMode() {
    ArNetPacket p = new ArNetPacket();
    writeMode(p);
    server.broadcastPacketTcp(p, requests.get("cameraModeUpdated"));
  }

  /** Cycle thread: while looking at a point, pans towards it (ARIA's user task). */
  private void followPoint() {
    ArPose at = lookAt;
    if (at == null) {
      return;
    }
    ArPose me = robot.getPose();
    // ARIA pans positive to the right: the opposite of the heading change towards the point.
    double pan = -ArMath.subAngle(me.findAngleTo(at), me.th());
    if (Math.abs(pan - camera.getPan()) > 0.5 || Math.abs(camera.getTilt()) > 0.5) {
      camera.panTilt(pan, 0);
    }
  }

  private double zoomRange() {
    return camera.getMaxZoom() - camera.getMinZoom();
  }

  private double zoomRatio() {
    double range = zoomRange();
    return range == 0 ? 0 : (camera.getZoom() - camera.getMinZoom()) / range;
  }

  /** ARIA's "double": a byte2 of the value × 100 (kept within a byte2). */
  private static void doubleToBuf(ArNetPacket p, double v) {
    p.byte2ToBuf((int) Math.max(Short.MIN_VALUE, Math.min(Short.MAX_VALUE, v * DOUBLE_FACTOR)));
  }

  /** ARIA's "double" read back; missing bytes read as 0, as ARIA's packets do. */
  private static double bufToDouble(ArNetPacket p) {
    return p.getRemaining() >= 2 ? p.bufToByte2() / DOUBLE_FACTOR : 0;
  }

  private static int bufToByte(ArNetPacket p) {
    return p.getRemaining() >= 1 ? p.bufToByte() : 0;
  }

  @Override
  public String toString() {
    return String.format(
        Locale.ROOT,
        "ArServerHandlerCamera[%s, %s, pan %.1f tilt %.1f]",
        cameraName.isEmpty() ? "no name" : cameraName,
        camera.getTypeName(),
        camera.getPan(),
        camera.getTilt());
  }
}
