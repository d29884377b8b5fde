package org.jaria.sim;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.ArRobotPacketReceiver;
import org.jaria.protocol.CommandCodec;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.StandardSip;

/**
 * A bare ARCOS client for tests, driven in lockstep with a {@link SimWorld}: it reads after every
 * tick (as a step listener) and keeps a copy of every packet and every byte it received.
 */
final class ArcosTestClient {

  final SimWorld world;
  final SimRobot robot;
  final ArDeviceConnection conn;
  final List<ArRobotPacket> received = new ArrayList<>();
  final ByteArrayOutputStream rawIn = new ByteArrayOutputStream();
  private final ArRobotPacketReceiver rx = new ArRobotPacketReceiver(new DropCounters("client"));
  private final ArRobotPacket out = new ArRobotPacket();
  private final byte[] buf = new byte[4096];
  private final Runnable listener = this::pump;
  private int pulseEveryTicks;
  private int ticks;

  /** Connects to {@code robot} in memory and listens to every tick. */
  ArcosTestClient(SimWorld world, SimRobot robot) {
    this.world = world;
    this.robot = robot;
    this.conn = robot.connectInMemory();
    world.addStepListener(listener);
  }

  /** Stops listening to the world. */
  void detach() {
    world.removeStepListener(listener);
  }

  /** Sends PULSE every {@code ms} of simulated time from now on (0 = never). */
  ArcosTestClient autoPulse(int ms) {
    pulseEveryTicks = (int) (ms / world.getTick().toMillis());
    return this;
  }

  void pump() {
    ticks++;
    try {
      int n;
      while ((n = conn.read(buf, 0, buf.length, 0)) > 0) {
        rawIn.write(buf, 0, n);
        rx.feed(
            buf,
            0,
            n,
            world.getClock().nanoTime(),
            p -> received.add(new ArRobotPacket().copyFrom(p)));
      }
    } catch (IOException e) {
      // the connection was dropped: tests look at what arrived before
    }
    if (pulseEveryTicks > 0 && ticks % pulseEveryTicks == 0) {
      com(ArCommands.PULSE);
    }
  }

  void send(ArRobotPacket p) {
    try {
      conn.write(p.getBuf(), 0, p.getLength());
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }

  void sendRaw(byte[] bytes) {
    try {
      conn.write(bytes, 0, bytes.length);
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }

  void com(int cmd) {
    send(CommandCodec.com(out, cmd));
  }

  void comInt(int cmd, int v) {
    send(CommandCodec.comInt(out, cmd, v));
  }

  void com2Bytes(int cmd, int hi, int lo) {
    send(CommandCodec.com2Bytes(out, cmd, hi, lo));
  }

  void comData(int cmd, byte[] data) {
    send(CommandCodec.comDataN(out, cmd, data, 0, data.length));
  }

  /** Sends a command with an arbitrary payload after the ID. */
  void comPayload(int cmd, byte[] payload) {
    out.empty().setID(cmd).dataToBuf(payload, 0, payload.length).finalizePacket();
    send(out);
  }

  void com(ArCommands cmd) {
    com(cmd.getNumber());
  }

  void comInt(ArCommands cmd, int v) {
    comInt(cmd.getNumber(), v);
  }

  void com2Bytes(ArCommands cmd, int hi, int lo) {
    com2Bytes(cmd.getNumber(), hi, lo);
  }

  void comData(ArCommands cmd, byte[] data) {
    comData(cmd.getNumber(), data);
  }

  void comPayload(ArCommands cmd, byte[] payload) {
    comPayload(cmd.getNumber(), payload);
  }

  /** Steps until a packet matching {@code p} arrived (at most {@code maxTicks}); returns it. */
  ArRobotPacket awaitPacket(Predicate<ArRobotPacket> p, int maxTicks) {
    int from = received.size();
    for (int i = 0; i < maxTicks; i++) {
      for (int k = from; k < received.size(); k++) {
        if (p.test(received.get(k))) {
          return received.get(k);
        }
      }
      from = received.size();
      world.step();
    }
    for (int k = from; k < received.size(); k++) {
      if (p.test(received.get(k))) {
        return received.get(k);
      }
    }
    throw new AssertionError(
        "no matching packet within " + maxTicks + " ticks; got " + received.size());
  }

  /** Steps until a packet with this ID arrives. */
  ArRobotPacket awaitId(int id) {
    return awaitPacket(q -> q.getID() == id, 500);
  }

  /** SYNC0/1/2, OPEN, ENABLE 1, as ARIA connects. */
  ArcosTestClient open() {
    for (int sync = 0; sync < 3; sync++) {
      com(sync);
      awaitId(sync);
    }
    comInt(ArCommands.OPEN, 1);
    awaitPacket(q -> PacketIds.isStandardSip(q.getID()), 50);
    comInt(ArCommands.ENABLE, 1);
    world.step();
    return this;
  }

  /** The SIPs received so far, decoded. */
  List<StandardSip> sips() {
    List<StandardSip> out = new ArrayList<>();
    for (ArRobotPacket p : received) {
      if (PacketIds.isStandardSip(p.getID())) {
        StandardSip s = new StandardSip();
        if (s.decode(p)) {
          out.add(s);
        }
      }
    }
    return out;
  }

  /** The last SIP received. */
  StandardSip lastSip() {
    List<StandardSip> s = sips();
    if (s.isEmpty()) {
      throw new AssertionError("no SIP received yet");
    }
    return s.get(s.size() - 1);
  }

  /** Packets with this ID received so far. */
  /** Every packet received since the last {@link #clear()}. */
  List<ArRobotPacket> all() {
    return List.copyOf(received);
  }

  List<ArRobotPacket> packets(int id) {
    return received.stream().filter(p -> p.getID() == id).toList();
  }

  void clear() {
    received.clear();
  }
}
