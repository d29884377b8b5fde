package org.jaria.net.data;

import java.util.ArrayList;
import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.NetEncodable;

/**
 * The current readings of every range device of the robot ({@code "getSensorCurrent"}), taken in
 * one robot cycle.
 *
 * @param counter the robot's cycle counter when they were taken
 * @param devices one entry per device
 */
public record SensorReadings(long counter, List<RangeReadings> devices) implements NetEncodable {

  /** Copies the list. */
  public SensorReadings {
    devices = List.copyOf(devices);
  }

  /** The readings of the device called {@code name}, or null. */
  public RangeReadings find(String name) {
    for (RangeReadings r : devices) {
      if (r.device().equals(name)) {
        return r;
      }
    }
    return null;
  }

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(2).intToBuf(counter).arrayToBuf(devices.size());
    for (RangeReadings r : devices) {
      r.write(out);
    }
  }

  /** Reads what {@link #write} wrote. */
  public static SensorReadings read(ArNetPacket in) {
    int n = Fields.begin(in, 2, "sensor readings");
    long counter = in.bufToLong();
    int k = in.bufToArray();
    List<RangeReadings> l = new ArrayList<>(k);
    for (int i = 0; i < k; i++) {
      l.add(RangeReadings.read(in));
    }
    Fields.end(in, n, 2);
    return new SensorReadings(counter, l);
  }
}
