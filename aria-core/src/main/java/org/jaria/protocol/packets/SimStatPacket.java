package org.jaria.protocol.packets;

import org.jaria.protocol.ArRobotPacket;

/**
 * SIMSTAT (0x62), MobileSim's status packet: flags, loop intervals and the robot's true pose (which
 * odometry error does not touch), and, for georeferenced maps, a simulated GPS position.
 *
 * @param flags bit 0 map loaded, bit 1 map georeferenced, bit 2 odometry error data present
 * @param simInterval simulated ms per loop
 * @param realInterval real ms a loop should take
 * @param lastInterval real ms the last loop took
 * @param trueX true x, mm
 * @param trueY true y, mm
 * @param trueZ true z, mm
 * @param trueTh true heading, degrees
 * @param latitude degrees × 10⁶ (valid with flag bit 1)
 * @param longitude degrees × 10⁶ (valid with flag bit 1)
 * @param altitude cm (valid with flag bit 1)
 * @param gpsQuality 100 good, 0 bad area, −1 no GPS
 * @param odomErrorX odometry error x, mm × 10⁶ (valid with flag bit 2)
 * @param odomErrorY odometry error y, mm × 10⁶
 * @param odomErrorTh odometry error heading, degrees × 10⁶
 */
public record SimStatPacket(
    long flags,
    int simInterval,
    int realInterval,
    int lastInterval,
    int trueX,
    int trueY,
    int trueZ,
    int trueTh,
    int latitude,
    int longitude,
    int altitude,
    int gpsQuality,
    int odomErrorX,
    int odomErrorY,
    int odomErrorTh) {

  /** Flag: the simulator has a map. */
  public static final long FLAG_HAVE_MAP = 1;

  /** Flag: the map has an origin georeference. */
  public static final long FLAG_GEOREFERENCED = 2;

  /** Flag: odometry error fields are meaningful. */
  public static final long FLAG_ODOMETRY_ERROR = 4;

  /** Decodes {@code p}, or returns {@code null} if it is not a whole SIMSTAT packet. */
  public static SimStatPacket decode(ArRobotPacket p) {
    if (p.getID() != PacketIds.SIMSTAT) {
      return null;
    }
    p.resetRead();
    p.bufToByte();
    p.bufToByte();
    long flags = p.bufToUByte4();
    int sim = p.bufToUByte2();
    int real = p.bufToUByte2();
    int last = p.bufToUByte2();
    int x = p.bufToByte4();
    int y = p.bufToByte4();
    int z = p.bufToByte4();
    int th = p.bufToByte4();
    if (!p.isValid()) {
      return null;
    }
    int lat = p.bufToByte4();
    int lon = p.bufToByte4();
    int alt = p.bufToByte4();
    int gps = p.bufToByte();
    int ex = p.bufToByte4();
    int ey = p.bufToByte4();
    int eth = p.bufToByte4();
    // The tail is newer; an older simulator stops after the pose.
    return new SimStatPacket(flags, sim, real, last, x, y, z, th, lat, lon, alt, gps, ex, ey, eth);
  }

  /** Writes this packet into {@code p} and finalizes it. */
  public ArRobotPacket encode(ArRobotPacket p) {
    p.empty().setID(PacketIds.SIMSTAT).byteToBuf(0).byteToBuf(0).uByte4ToBuf(flags);
    p.uByte2ToBuf(simInterval).uByte2ToBuf(realInterval).uByte2ToBuf(lastInterval);
    p.byte4ToBuf(trueX).byte4ToBuf(trueY).byte4ToBuf(trueZ).byte4ToBuf(trueTh);
    p.byte4ToBuf(latitude).byte4ToBuf(longitude).byte4ToBuf(altitude).byteToBuf(gpsQuality);
    p.byte4ToBuf(odomErrorX).byte4ToBuf(odomErrorY).byte4ToBuf(odomErrorTh);
    return p.finalizePacket();
  }
}
