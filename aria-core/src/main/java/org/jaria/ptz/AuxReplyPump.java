package org.jaria.ptz;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.function.Consumer;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.SerAuxPacket;
import org.jaria.robot.ArListPos;
import org.jaria.robot.ArRobot;

/**
 * Brings a device's answers back from the robot's AUX1 port. ARCOS answers GETAUX n with a
 * SERAUXpac only once n bytes have arrived, so a driver says how many bytes it expects ({@link
 * #expect}) and the pump keeps exactly one GETAUX outstanding until they have all come, handing
 * each SERAUXpac's bytes to the driver's parser in order. A port with nothing attached answers with
 * no bytes: the pump then stops asking.
 *
 * <p>Thread-safe: drivers call {@link #expect} from any thread; the robot's thread delivers
 * packets.
 */
final class AuxReplyPump {

  private final ArRobot robot;
  private final Consumer<byte[]> parser;
  private final Object lock = new Object();

  @GuardedBy("lock")
  private int outstanding;

  @GuardedBy("lock")
  private boolean requestPending;

  @GuardedBy("lock")
  private long bytesReceived;

  /** Pumps {@code robot}'s AUX1 answers into {@code parser} (called on the robot's thread). */
  AuxReplyPump(ArRobot robot, Consumer<byte[]> parser) {
    this.robot = robot;
    this.parser = parser;
    robot.addPacketHandler(this::handle, ArListPos.LAST);
  }

  /** Expects {@code n} more bytes from the device; asks for them if no request is out. */
  void expect(int n) {
    boolean ask;
    int count;
    synchronized (lock) {
      outstanding += n;
      ask = !requestPending && outstanding > 0;
      requestPending |= ask;
      count = Math.min(outstanding, 200);
    }
    if (ask) {
      robot.comInt(ArCommands.GETAUX, count);
    }
  }

  /** Forgets what is expected and empties the port's buffer (GETAUX 0). */
  void flush() {
    synchronized (lock) {
      outstanding = 0;
      requestPending = false;
    }
    robot.comInt(ArCommands.GETAUX, 0);
  }

  /** Bytes still expected. */
  int outstanding() {
    synchronized (lock) {
      return outstanding;
    }
  }

  /** Bytes the device has sent back. */
  long bytesReceived() {
    synchronized (lock) {
      return bytesReceived;
    }
  }

  private boolean handle(ArRobotPacket p) {
    if (p.getID() != PacketIds.SERAUX1) {
      return false;
    }
    SerAuxPacket aux = SerAuxPacket.decode(p);
    if (aux == null) {
      return true;
    }
    byte[] data = aux.data();
    boolean ask;
    int count;
    synchronized (lock) {
      requestPending = false;
      bytesReceived += data.length;
      // no bytes: nothing is attached to the port, so asking again would only repeat that
      outstanding = data.length == 0 ? 0 : Math.max(0, outstanding - data.length);
      ask = outstanding > 0;
      requestPending = ask;
      count = Math.min(outstanding, 200);
    }
    if (ask) {
      robot.comInt(ArCommands.GETAUX, count);
    }
    if (data.length > 0) {
      parser.accept(data);
    }
    return true;
  }
}
