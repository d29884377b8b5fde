package org.jaria.net.server.info;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.net.ArNetPacket;
import org.jaria.net.data.Points;
import org.jaria.net.data.RangeReadings;
import org.jaria.net.data.SensorReadings;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.TextLimits;
import org.jaria.net.server.Where;
import org.jaria.range.ArRangeDevice;
import org.jaria.robot.ArRobot;

/**
 * The robot's range readings for clients (ArNetworking's {@code ArServerInfoSensor}): {@code
 * "getSensorList"}, {@code "getSensorCurrent"} and {@code "getSensorCumulative"} (one named
 * device's readings, in ArNetworking's layouts; request them at an interval with the sensor's name
 * as the argument). Range devices may be read from any thread, so nothing of this runs on the
 * robot's cycle.
 */
public final class ArServerInfoSensor {

  private final ArRobot robot;

  /** Registers the sensor data with {@code server}. */
  public ArServerInfoSensor(ArServerBase server, ArRobot robot) {
    this.robot = robot;
    server.addData(
        "getSensorList",
        "gets a list of sensors attached to the robot",
        "none",
        "byte2: numSensors,  repeating for numSensors: string: sensorName",
        "SensorInfo",
        "RETURN_COMPLEX",
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
    server.addData(
        "getSensorCurrent",
        "gets the current sensor readings for requested sensors",
        "string: sensorName",
        "byte2: numReadings string: sensorName, repeating for numReadings times: byte4: x byte4:"
            + " y.... if numReadings is -1 it means no sensor by that name",
        "SensorInfo",
        "RETURN_COMPLEX",
        Where.WORKER,
        (client, request, reply) -> readings(request.bufToStr(), false, reply));
    server.addData(
        "getSensorCumulative",
        "gets the cumulative sensor readings for requested sensors",
        "string: sensorName",
        "byte2: numReadings string: sensorName, repeating for numReadings times: byte4: x byte4:"
            + " y.... if numReadings is -1 it means no sensor by that name",
        "SensorInfo",
        "RETURN_COMPLEX",
        Where.WORKER,
        (client, request, reply) -> readings(request.bufToStr(), true, reply));
  }

  private void readings(String name, boolean cumulative, ArNetPacket reply) {
    ArRangeDevice d = name.length() > TextLimits.MAX_NAME ? null : robot.findRangeDevice(name);
    if (d == null) {
      // ArNetworking's answer for a sensor it does not have (the name echoed, cut).
      reply.byte2ToBuf(-1).strToBuf(TextLimits.clip(name, TextLimits.MAX_NAME));
      return;
    }
    List<ArPose> l = cumulative ? d.getCumulativeReadings() : d.getCurrentReadings();
    new RangeReadings(d.getName(), d.getMaxRange(), Points.of(l)).write(reply);
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
