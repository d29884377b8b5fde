package org.jaria.net.server.info;

import java.util.ArrayList;
import java.util.List;
import org.jaria.net.data.Points;
import org.jaria.net.data.RangeReadings;
import org.jaria.net.data.SensorReadings;
import org.jaria.net.protocol.NetError;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.NetRequestException;
import org.jaria.net.server.PolledPublication;
import org.jaria.net.server.Where;
import org.jaria.range.ArRangeDevice;
import org.jaria.robot.ArRobot;

/**
 * The robot's range readings for clients (ArNetworking's {@code ArServerInfoSensor}): {@code
 * "getSensorList"}, {@code "getSensorCurrent"} (published: every device's current readings, taken
 * once per robot cycle and only while someone is subscribed) and {@code "getSensorCumulative"} (one
 * device's cumulative readings, on request). Range devices may be read from any thread, so nothing
 * of this runs on the robot's cycle.
 */
public final class ArServerInfoSensor {

  private final ArRobot robot;

  /** Registers the sensor data with {@code server}. */
  public ArServerInfoSensor(ArServerBase server, ArRobot robot) {
    this.robot = robot;
    server.addData(
        "getSensorList",
        "the names of the robot's range devices",
        "none",
        "array of string",
        "SensorInfo",
        Where.WORKER,
        (client, request, reply) -> {
          List<String> names = new ArrayList<>();
          for (ArRangeDevice d : robot.getRangeDeviceList()) {
            names.add(d.getName());
          }
          reply.byte2ToBuf(names.size());
          for (String s : names) {
            reply.strToBuf(s);
          }
        });
    server.addPublishedData(
        "getSensorCurrent",
        "every range device's current readings, global mm",
        "SensorReadings [counter, [[device, maxRange, points]...]]",
        "SensorInfo",
        PolledPublication.keyed(robot::getCounter, this::current));
    server.addData(
        "getSensorCumulative",
        "one range device's cumulative readings, global mm",
        "string device",
        "RangeReadings [device, maxRange, points]",
        "SensorInfo",
        Where.WORKER,
        (client, request, reply) -> {
          String name = request.bufToStr();
          ArRangeDevice d = robot.findRangeDevice(name);
          if (d == null) {
            throw new NetRequestException(
                NetError.BAD_ARGUMENTS, "no range device '" + name + "'; see getSensorList");
          }
          new RangeReadings(d.getName(), d.getMaxRange(), Points.of(d.getCumulativeReadings()))
              .write(reply);
        });
  }

  /** Every device's current readings now. */
  public SensorReadings current() {
    List<RangeReadings> l = new ArrayList<>();
    for (ArRangeDevice d : robot.getRangeDeviceList()) {
      l.add(new RangeReadings(d.getName(), d.getMaxRange(), Points.of(d.getCurrentReadings())));
    }
    return new SensorReadings(robot.getCounter(), l);
  }
}
