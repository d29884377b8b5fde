package org.jaria.tools.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.SplittableRandom;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.CommandCodec;
import org.jaria.sim.SimRobot;

/**
 * A minimal in-process ARCOS client for benchmarks: connects to a simulated robot, opens it,
 * enables the motors and wanders (a new random speed and turn rate every two seconds), reading and
 * discarding everything the robot sends. With the laser on it first sends what ARIA's {@code
 * ArSimulatedLaser} sends (field of view −90..90° at 1°, then "laser on, extended packets"). Driven
 * from the world's step listener, so it costs what a real client's reading costs and nothing more.
 */
final class ScriptedClient {

  private final ArDeviceConnection conn;
  private final ArRobotPacket out = new ArRobotPacket();
  private final byte[] buf = new byte[8192];
  private final SplittableRandom rng;
  private final boolean laser;
  private int tick;
  private long bytesRead;

  ScriptedClient(SimRobot robot, long seed, boolean laser) {
    this.conn = robot.connectInMemory();
    this.rng = new SplittableRandom(seed);
    this.laser = laser;
  }

  /** Called after every world tick. */
  void onTick() {
    drain();
    switch (tick) {
      case 0 -> send(CommandCodec.com(out, 0));
      case 1 -> send(CommandCodec.com(out, 1));
      case 2 -> send(CommandCodec.com(out, 2));
      case 3 -> send(CommandCodec.comInt(out, 1, 1));
      case 4 -> send(CommandCodec.comInt(out, 4, 1));
      case 6 -> {
        if (laser) {
          send(CommandCodec.comInt(out, 36, -90));
          send(CommandCodec.comInt(out, 37, 90));
          send(CommandCodec.comInt(out, 38, 100));
          send(CommandCodec.comInt(out, 35, 2));
        }
      }
      default -> {
        if (tick % 200 == 5) {
          send(CommandCodec.comInt(out, 11, 200 + rng.nextInt(500)));
          send(CommandCodec.comInt(out, 21, rng.nextInt(61) - 30));
        } else if (tick % 50 == 0) {
          send(CommandCodec.com(out, 0));
        }
      }
    }
    tick++;
  }

  private void send(ArRobotPacket p) {
    try {
      conn.write(p.getBuf(), 0, p.getLength());
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }

  private void drain() {
    try {
      int n;
      while ((n = conn.read(buf, 0, buf.length, 0)) > 0) {
        bytesRead += n;
      }
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }

  long bytesRead() {
    return bytesRead;
  }
}
