package org.jaria.net.data;

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

  /** Writes the first device's readings in ArNetworking's layout (see {@link RangeReadings}). */
  @Override
  public void write(ArNetPacket out) {
    if (devices.isEmpty()) {
      out.byte2ToBuf(0).strToBuf("");
    } else {
      devices.get(0).write(out);
    }
  }

  /**
   * Reads one getSensorCurrent packet (ArNetworking carries one sensor per packet) as readings of
   * that one device; no devices if the server has no such sensor.
   */
  public static SensorReadings read(ArNetPacket in) {
    RangeReadings r = RangeReadings.read(in);
    return new SensorReadings(0, r == null ? List.of() : List.of(r));
  }
}
