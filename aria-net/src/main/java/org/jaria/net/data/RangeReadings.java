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

  private static final int FIELDS = 3;

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(FIELDS).strToBuf(device).doubleToBuf(maxRange);
    current.write(out);
  }

  /** Reads what {@link #write} wrote. */
  public static RangeReadings read(ArNetPacket in) {
    int n = Fields.begin(in, FIELDS, "range readings");
    RangeReadings r = new RangeReadings(in.bufToStr(), in.bufToDouble(), Points.read(in));
    Fields.end(in, n, FIELDS);
    return r;
  }
}
