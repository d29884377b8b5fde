package org.jaria.protocol.packets;

import org.jaria.protocol.ArRobotPacket;

/**
 * TCM2pac (0xC0): the TCM2 compass module. The heading comes first, as ARIA's {@code
 * ArTCMCompassRobot} reads it (the spec's field list omits it; the thesis's byte count only adds up
 * with it).
 *
 * @param heading compass heading, 0.1°
 * @param pitch pitch, 0.1°
 * @param roll roll, 0.1°
 * @param magX magnetic field X
 * @param magY magnetic field Y
 * @param magZ magnetic field Z
 * @param temperature temperature
 * @param error error bitmap
 * @param calH horizontal calibration score
 * @param calV vertical calibration score
 * @param calM magnetic calibration score
 */
public record Tcm2Packet(
    int heading,
    int pitch,
    int roll,
    int magX,
    int magY,
    int magZ,
    int temperature,
    int error,
    int calH,
    int calV,
    int calM) {

  /** Decodes {@code p}, or returns {@code null} if it is not a whole TCM2pac. */
  public static Tcm2Packet decode(ArRobotPacket p) {
    if (p.getID() != PacketIds.TCM2) {
      return null;
    }
    p.resetRead();
    Tcm2Packet t =
        new Tcm2Packet(
            p.bufToByte2(),
            p.bufToByte2(),
            p.bufToByte2(),
            p.bufToByte2(),
            p.bufToByte2(),
            p.bufToByte2(),
            p.bufToByte2(),
            p.bufToByte2(),
            p.bufToUByte(),
            p.bufToUByte(),
            p.bufToByte2());
    return p.isValid() ? t : null;
  }

  /** Writes this packet into {@code p} and finalizes it. */
  public ArRobotPacket encode(ArRobotPacket p) {
    p.empty().setID(PacketIds.TCM2).byte2ToBuf(heading);
    p.byte2ToBuf(pitch).byte2ToBuf(roll).byte2ToBuf(magX).byte2ToBuf(magY).byte2ToBuf(magZ);
    p.byte2ToBuf(temperature).byte2ToBuf(error).uByteToBuf(calH).uByteToBuf(calV);
    return p.byte2ToBuf(calM).finalizePacket();
  }
}
