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

  private static final int FIELDS = 10;

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(FIELDS)
        .strToBuf(name)
        .strToBuf(type)
        .strToBuf(subType)
        .doubleToBuf(width)
        .doubleToBuf(lengthFront)
        .doubleToBuf(lengthRear)
        .doubleToBuf(radius)
        .intToBuf(numSonar)
        .doubleToBuf(maxTransVel)
        .doubleToBuf(maxRotVel);
  }

  /** Reads what {@link #write} wrote. */
  public static PhysicalInfo read(ArNetPacket in) {
    int n = Fields.begin(in, FIELDS, "physical info");
    PhysicalInfo p =
        new PhysicalInfo(
            in.bufToStr(),
            in.bufToStr(),
            in.bufToStr(),
            in.bufToDouble(),
            in.bufToDouble(),
            in.bufToDouble(),
            in.bufToDouble(),
            in.bufToInt(),
            in.bufToDouble(),
            in.bufToDouble());
    Fields.end(in, n, FIELDS);
    return p;
  }
}
