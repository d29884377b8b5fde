package org.jaria.net.data;

import org.jaria.net.ArNetPacket;
import org.jaria.net.NetEncodable;

/**
 * What the robot is and how big ({@code "physicalInfo"}): a monitor draws it from this.
 *
 * @param name the robot's name
 * @param type robot type ("Pioneer")
 * @param subType model ("p3dx-sh")
 * @param width mm
 * @param lengthFront centre to front, mm
 * @param lengthRear centre to rear, mm
 * @param radius mm
 * @param numSonar sonar transducers
 * @param maxTransVel top translational velocity, mm/s
 * @param maxRotVel top rotational velocity, deg/s
 */
public record PhysicalInfo(
    String name,
    String type,
    String subType,
    double width,
    double lengthFront,
    double lengthRear,
    double radius,
    int numSonar,
    double maxTransVel,
    double maxRotVel)
    implements NetEncodable {

  /**
   * Writes ArNetworking's "physicalInfo" layout: string robotType; string robotSubType; byte2
   * width; byte2 lengthFront; byte2 lengthRear; byte lateral control (0).
   */
  @Override
  public void write(ArNetPacket out) {
    out.strToBuf(type)
        .strToBuf(subType)
        .byte2ToBuf((int) Math.round(width))
        .byte2ToBuf((int) Math.round(lengthFront))
        .byte2ToBuf((int) Math.round(lengthRear))
        .byteToBuf(0);
  }

  /**
   * Reads ArNetworking's "physicalInfo" layout. What it does not carry gets neutral values: name =
   * type, radius = half the width, no sonar count (0) and no speed limits (0).
   */
  public static PhysicalInfo read(ArNetPacket in) {
    String type = in.bufToStr();
    String subType = in.bufToStr();
    double w = in.bufToByte2();
    double front = in.bufToByte2();
    double rear = in.bufToByte2();
    if (in.hasMore()) {
      in.bufToByte();
    }
    return new PhysicalInfo(type, type, subType, w, front, rear, w / 2, 0, 0, 0);
  }
}
