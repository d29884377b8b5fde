package org.jaria.sim.server;

import java.nio.charset.StandardCharsets;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.ArgKind;
import org.jaria.protocol.CommandCodec;
import org.jaria.protocol.DropReason;
import org.jaria.sim.robot.MotionController;
import org.jaria.sim.robot.RobotBody;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Executes the client commands of an open ARCOS session on the simulated robot (the table in the
 * protocol spec). Unknown commands are ignored and logged once per number.
 *
 * <p>Commands 35–38 have two meanings: ADSEL, GRIPPERVAL, GRIPREQUEST and GYROCALCW on ARCOS, but
 * the laser set-up commands of the older simulator that ARIA's {@code ArSimulatedLaser} still sends
 * (enable, start angle, end angle, increment). Like MobileSim, a robot that carries a laser takes
 * them as laser commands; a robot without one takes the ARCOS meanings.
 */
final class CommandHandler {

  private static final Logger log = LoggerFactory.getLogger(CommandHandler.class);

  private final ArcosSession s;
  private final RobotBody body;

  CommandHandler(ArcosSession session) {
    this.s = session;
    this.body = session.body;
  }

  void handle(ArRobotPacket p) {
    int id = p.getID();
    MotionController m = body.motion();
    double heading = body.odometry().getTh();
    boolean laserCompat = body.laser() != null;
    switch (id) {
      case 0 -> {} // PULSE: only resets the watchdog
      case 1 -> {} // OPEN while open: nothing to do
      case 2 -> s.close();
      case 3 -> body.sonar().polling(CommandCodec.readDataArg(p));
      case 4 -> m.enableMotors(intArg(p, 1) != 0);
      case 5 -> m.setTransAccel(intArg(p, 0));
      case 6 -> m.setTransVelMax(intArg(p, 0));
      case 7 -> seto(p);
      case 8 -> m.move(intArg(p, 0));
      case 9, 21 -> m.setRotVel(intArg(p, 0));
      case 10 -> m.setRotVelMax(intArg(p, 0));
      case 11 -> m.setVel(intArg(p, 0));
      case 12 -> m.setHeading(intArg(p, 0));
      case 13 -> m.deltaHeading(intArg(p, 0), heading);
      case 15 -> body.io().say(CommandCodec.readDataArg(p));
      case 17 -> s.joyMode = clampMode(intArg(p, 1));
      case 18 ->
          s.send(
              ServerPackets.config(
                  s.out(),
                  body,
                  s.host.sipCycleMillis(),
                  s.host.watchdogMillis(),
                  s.gyroCw,
                  s.gyroCcw));
      case 19 -> s.encoderMode = clampMode(intArg(p, 1));
      case 20 -> m.setRotVelMaxDir(intArg(p, 0));
      case 22 -> m.deltaControlHeading(intArg(p, 0), heading);
      case 23 -> m.setRotAccel(intArg(p, 0));
      case 28 -> body.sonar().sonarCommand(intArg(p, 1));
      case 29 -> m.stop();
      case 30 -> {
        int bits = bits16(p);
        body.io().digOut(bits >> 8, bits & 0xFF);
      }
      case 32 -> {
        int bits = bits16(p);
        double div = body.model().getVel2Divisor();
        m.setVel2((byte) (bits >> 8) * div, (byte) bits * div);
      }
      case 33 -> {
        if (body.gripper() != null) {
          body.gripper().command(intArg(p, 0));
        }
      }
      case 35 -> {
        if (laserCompat) {
          s.laserMode = clampMode(intArg(p, 0));
        } else {
          body.io().selectAnalog(intArg(p, 0));
        }
      }
      case 36 -> {
        if (laserCompat) {
          body.laser().setStart(intArg(p, 0));
        } else if (body.gripper() != null) {
          body.gripper().setGripperVal(intArg(p, 0));
        }
      }
      case 37 -> {
        if (laserCompat) {
          body.laser().setEnd(intArg(p, 0));
        } else {
          s.gripMode = clampMode(intArg(p, 1));
        }
      }
      case 38 -> {
        if (laserCompat) {
          body.laser().setIncrement(intArg(p, 100) / 100.0);
        } else {
          s.gyroCw = intArg(p, 0) & 0xFFFF;
        }
      }
      case 39 -> s.gyroCcw = intArg(p, 0) & 0xFFFF;
      case 40 -> s.ioMode = clampMode(intArg(p, 1));
      case 44 -> body.setBumpStall(intArg(p, 0));
      case 45 -> tcm2(intArg(p, 1));
      case 48 -> body.sonar().setCycle(intArg(p, 40));
      case 55 -> m.eStop();
      case 58 -> {
        if (body.gyro() != null) {
          body.gyro().setStreaming(intArg(p, 1) != 0);
        }
      }
      case 88 -> body.odometry().setRevCount(intArg(p, 0));
      case 89 -> body.odometry().setDriftFactor(intArg(p, 0));
      case 92 -> body.io().setSound(intArg(p, 1) != 0);
      case 93 -> body.odometry().setTicksMm(intArg(p, 0));
      case 224 -> simSetPose(p);
      case 225 -> body.resetToStart();
      case 230 -> s.laserMode = body.laser() != null ? clampMode(intArg(p, 1)) : 0;
      case 231 -> {
        if (body.laser() != null) {
          body.laser().setStart(intArg(p, -90));
        }
      }
      case 232 -> {
        if (body.laser() != null) {
          body.laser().setEnd(intArg(p, 90));
        }
      }
      case 233 -> {
        if (body.laser() != null) {
          body.laser().setIncrement(intArg(p, 100) / 100.0);
        }
      }
      case 236 -> simCtrl(p);
      case 237 -> simStat(intArg(p, 1));
      case 238 ->
          log.info("{}: message from client: {}", body.name(), CommandCodec.readStringArg(p));
      case 239 -> s.host.exitRequested(intArg(p, 0), body.name());
      case 250 -> body.io().batTest(intArg(p, 0));
      case 253, 255 -> {
        log.warn("{}: client sent {} (controller reset); closing the session", body.name(), id);
        s.close();
      }
      // Known commands with nothing to simulate: serial ports, bauds, LCD, charger, PID gains,
      // joystick drive, motor stall settings, battery info.
      case 42, 43, 47, 50, 51, 52, 53, 56, 59, 60, 61, 62, 66, 67, 68, 82, 83, 84, 85, 86, 87 -> {}
      default -> s.host.unknownCommand(id, body.name());
    }
  }

  private static int clampMode(int v) {
    return v <= 0 ? 0 : (v == 1 ? 1 : 2);
  }

  /** An integer argument (0x3B positive, 0x1B negative); {@code missing} if there is none. */
  private static int intArg(ArRobotPacket p, int missing) {
    return CommandCodec.readIntArg(p, missing);
  }

  /** The raw 16 bits of a two-byte argument (VEL2, DIGOUT), whatever sign byte came with it. */
  private static int bits16(ArRobotPacket p) {
    p.resetRead();
    if (p.getDataLength() < 3) {
      return 0;
    }
    int type = p.bufToUByte();
    int mag = p.bufToUByte2();
    return type == ArgKind.NEG_INT_ARG ? -mag & 0xFFFF : mag;
  }

  /** SETO: odometry to 0,0,0, or to x, y, th given as int32 (like SIM_SET_POSE) or int16. */
  private void seto(ArRobotPacket p) {
    p.resetRead();
    int len = p.getDataLength();
    if (len >= 13) {
      p.bufToUByte();
      body.odometry().setPose(p.bufToByte4(), p.bufToByte4(), p.bufToByte4());
    } else if (len >= 7) {
      p.bufToUByte();
      body.odometry().setPose(p.bufToByte2(), p.bufToByte2(), p.bufToByte2());
    } else {
      body.odometry().setPose(0, 0, 0);
    }
  }

  /** SIM_SET_POSE: a type byte (ignored), then x, y, th as int32 (mm, mm, degrees). */
  private void simSetPose(ArRobotPacket p) {
    p.resetRead();
    if (p.getDataLength() < 13) {
      s.drops().drop(DropReason.MALFORMED, "SIM_SET_POSE with " + p.getDataLength() + " bytes");
      return;
    }
    p.bufToUByte();
    body.setTruePose(new ArPose(p.bufToByte4(), p.bufToByte4(), p.bufToByte4()));
  }

  /** SIM_CTRL: a type byte, an int16 op code, then op data. */
  private void simCtrl(ArRobotPacket p) {
    p.resetRead();
    if (p.getDataLength() < 3) {
      s.drops().drop(DropReason.MALFORMED, "SIM_CTRL without an op code");
      return;
    }
    p.bufToUByte();
    int op = p.bufToByte2();
    switch (op) {
      case 1, 2 -> {
        int len = Math.min(p.bufToUByte2(), p.remaining());
        byte[] raw = new byte[len];
        p.bufToData(raw, 0, len);
        int end = 0;
        while (end < len && raw[end] != 0) {
          end++;
        }
        s.host.loadMapRequested(new String(raw, 0, end, StandardCharsets.ISO_8859_1), body.name());
      }
      case 3, 4, 5 -> {} // map master mode off, log rotation, state log: nothing to do here
      case 6 -> s.send(ServerPackets.simInfo(s.out(), body));
      case 7 -> s.host.ghostRequested(body.index());
      default -> log.warn("{}: unknown SIM_CTRL op {} ignored", body.name(), op);
    }
  }

  /** SIM_STAT: 0 stop, 1 one packet now, 2 one before every SIP. */
  private void simStat(int arg) {
    if (arg == 1) {
      s.send(ServerPackets.simStat(s.out(), body, s.host));
    }
    s.simStatMode = arg == 2 ? 2 : (arg == 0 ? 0 : s.simStatMode);
  }

  /** TCM2: 0 off, 1 compass, 2 one TCM2pac, 3 continuous, 4/5 calibrate, 6 stop + one, 7 reset. */
  private void tcm2(int mode) {
    switch (mode) {
      case 0, 1, 3 -> body.io().setCompassMode(mode);
      case 2 -> {
        if (body.io().getCompassMode() == 0) {
          body.io().setCompassMode(1);
        }
        s.tcm2Once = true;
      }
      case 4, 5 -> body.io().setCompassMode(1);
      case 6 -> {
        body.io().setCompassMode(1);
        s.tcm2Once = true;
      }
      case 7 -> body.io().setCompassMode(1);
      default -> s.host.unknownCommand(ArCommands.TCM2.getNumber(), body.name());
    }
  }
}
