package org.jaria.net.data;

import org.jaria.net.ArNetPacket;
import org.jaria.net.NetEncodable;

/**
 * The readings of one range device in global coordinates, mm.
 *
 * @param device the device's name ("sonar", "laser", "bumpers" ...)
 * @param maxRange the device's range, mm
 * @param current what it sees now
 */
public record RangeReadings(String device, double maxRange, Points current)
    implements NetEncodable {

  /**
   * Writes ArNetworking's getSensorCurrent/getSensorCumulative layout: byte2 number of readings;
   * string sensor name; then byte4 x, byte4 y (mm) for each reading. Readings that do not fit one
   * packet are left out.
   */
  @Override
  public void write(ArNetPacket out) {
    int n = Math.min(current.size(), (out.getWriteCapacity() - 2 - device.length() * 3 - 1) / 8);
    n = Math.max(0, Math.min(n, Short.MAX_VALUE));
    out.byte2ToBuf(n).strToBuf(device);
    for (int i = 0; i < n; i++) {
      out.byte4ToBuf(current.x(i)).byte4ToBuf(current.y(i));
    }
  }

  /**
   * Reads ArNetworking's sensor layout; null if the server says there is no such sensor (-1
   * readings). The layout does not carry the range, so {@code maxRange} is 0.
   */
  public static RangeReadings read(ArNetPacket in) {
    int n = in.bufToByte2();
    String name = in.bufToStr();
    if (n < 0) {
      return null;
    }
    if ((long) n * 8 > in.getRemaining()) {
      throw new org.jaria.net.ArNetPacketException(
          "sensor " + name + " announces " + n + " readings but has " + in.getRemaining() + " B");
    }
    int[] flat = new int[n * 2];
    for (int i = 0; i < flat.length; i++) {
      flat[i] = in.bufToByte4();
    }
    return new RangeReadings(name, 0, Points.ofFlat(flat, 2));
  }
}
