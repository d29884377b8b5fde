package org.jaria.protocol.packets;

import org.jaria.protocol.ArRobotPacket;

/**
 * JOYSTICKpac (0xF8): the robot's own joystick. Axes are 0..1023 centred near 512.
 *
 * @param button1 first button, 0 or 1
 * @param button2 second button, 0 or 1
 * @param x side-to-side axis
 * @param y forward-back axis
 * @param throttle throttle
 */
public record JoystickPacket(int button1, int button2, int x, int y, int throttle) {

  /** Decodes {@code p}, or returns {@code null} if it is not a whole JOYSTICKpac. */
  public static JoystickPacket decode(ArRobotPacket p) {
    if (p.getID() != PacketIds.JOYSTICK) {
      return null;
    }
    p.resetRead();
    JoystickPacket j =
        new JoystickPacket(
            p.bufToUByte(), p.bufToUByte(), p.bufToUByte2(), p.bufToUByte2(), p.bufToUByte2());
    return p.isValid() ? j : null;
  }

  /** Writes this packet into {@code p} and finalizes it. */
  public ArRobotPacket encode(ArRobotPacket p) {
    p.empty().setID(PacketIds.JOYSTICK).uByteToBuf(button1).uByteToBuf(button2);
    return p.uByte2ToBuf(x).uByte2ToBuf(y).uByte2ToBuf(throttle).finalizePacket();
  }
}
