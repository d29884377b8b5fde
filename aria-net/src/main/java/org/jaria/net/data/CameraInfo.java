package org.jaria.net.data;

import java.util.ArrayList;
import java.util.List;
import org.jaria.net.ArNetPacket;

/**
 * One camera of a robot as ArNetworking's {@code getCameraList} describes it: its name (the suffix
 * of its requests, "Cam1"), type ("VCC4"), the name and type to show people, and its commands —
 * each an {@code ArCameraCommands} name ("setCameraAbs"), the request that does it on this server
 * ("setCameraAbsCam1") and the interval to request it at (-1: when needed).
 *
 * <p>The packet: {@code byte2} number of cameras, then per camera four strings, {@code byte2}
 * number of commands, per command two strings and a {@code byte4}, then {@code byte2} number of
 * parameters (ArConfigArg layout; JAria's cameras have none).
 */
public record CameraInfo(
    String name, String type, String displayName, String displayType, List<Command> commands) {

  /** A command of the camera. */
  public record Command(String command, String requestName, int requestInterval) {}

  /** Copies the list. */
  public CameraInfo {
    commands = List.copyOf(commands);
  }

  /** Writes {@code cameras} in {@code getCameraList}'s layout. */
  public static void writeList(ArNetPacket p, List<CameraInfo> cameras) {
    p.byte2ToBuf(cameras.size());
    for (CameraInfo c : cameras) {
      p.strToBuf(c.name()).strToBuf(c.type()).strToBuf(c.displayName()).strToBuf(c.displayType());
      p.byte2ToBuf(c.commands().size());
      for (Command k : c.commands()) {
        p.strToBuf(k.command()).strToBuf(k.requestName()).byte4ToBuf(k.requestInterval());
      }
      p.byte2ToBuf(0);
    }
  }

  /**
   * Reads a {@code getCameraList} answer.
   *
   * @throws org.jaria.net.ArNetPacketException if it is cut short, or a camera has parameters
   *     (their layout is ArConfigArg's, which this reader does not follow)
   */
  public static List<CameraInfo> readList(ArNetPacket p) {
    int n = p.bufToByte2();
    List<CameraInfo> out = new ArrayList<>();
    for (int i = 0; i < n; i++) {
      String name = p.bufToStr();
      String type = p.bufToStr();
      String display = p.bufToStr();
      String displayType = p.bufToStr();
      int k = p.bufToByte2();
      List<Command> commands = new ArrayList<>();
      for (int j = 0; j < k; j++) {
        commands.add(new Command(p.bufToStr(), p.bufToStr(), p.bufToByte4()));
      }
      if (p.bufToByte2() != 0) {
        throw new org.jaria.net.ArNetPacketException(
            "camera " + name + " has parameters; reading them is not supported");
      }
      out.add(new CameraInfo(name, type, display, displayType, commands));
    }
    return out;
  }
}
