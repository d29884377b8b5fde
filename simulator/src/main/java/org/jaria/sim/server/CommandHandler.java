package org.jaria.sim.server;

import java.nio.charset.StandardCharsets;
import java.util.EnumSet;
import java.util.Set;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.ArgKind;
import org.jaria.protocol.CommandCodec;
import org.jaria.protocol.DropReason;
import org.jaria.protocol.packets.SerAuxPacket;
import org.jaria.sim.robot.LaserModel;
import org.jaria.sim.robot.MotionController;
import org.jaria.sim.robot.RobotBody;
import org.jaria.sim.robot.SimProfile;
import org.jaria.sim.robot.SrisimLaserSetup;
import org.jaria.sim.serial.AuxPort;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Executes the client commands of an open ARCOS session on the simulated robot (the table in the
 * protocol spec). Commands it does not carry out are recorded with the reason (see {@link
 * IgnoredCommand}) and logged once: numbers ARCOS does not know, real commands for hardware the
 * simulator does not have (arm, pan-tilt unit), and commands for a device this robot does not
 * carry.
 *
 * <p>Commands 35–38 mean ADSEL, GRIPPERVAL, GRIPREQUEST and GYROCALCW on ARCOS. The older SRISim
 * simulator used the same numbers for setting up the laser (enable, start angle, end angle,
 * increment) and ARIA's {@code ArSimulatedLaser} still sends them, so a robot with a laser takes
 * them that way by default, as MobileSim does; {@link
 * org.jaria.sim.RobotOptions#withLegacyLaserCommands} (MobileSim's {@code
 * --no-srisim-laser-compat}) gives them back their ARCOS meanings. With {@link
 * org.jaria.sim.RobotOptions#withSrisimCompat} 62, 66, 67 and 69 are SRISim's exit, set x, set y
 * and reset too.
 *
 * <p>TTY2/TTY3/TTY4 write to the AUX ports and GETAUX/GETAUX2/GETAUX3 read from them (see {@link
 * AuxPort}); AUX1 has a VC-C4 camera.
 */
final class CommandHandler {

  private static final Logger log = LoggerFactory.getLogger(CommandHandler.class);

  /**
   * Requests MobileSim leaves unanswered (it sends no ENCODERpac, IOpac, JOYSTICKpac or TCM2pac),
   * ignored in the {@code mobilesim} profile. GRIPREQUEST too, once it is not a laser command.
   */
  private static final Set<ArCommands> MOBILESIM_IGNORES =
      EnumSet.of(ArCommands.ENCODER, ArCommands.IOREQUEST, ArCommands.JOYREQUEST, ArCommands.TCM2);

  private final ArcosSession s;
  private final RobotBody body;

  CommandHandler(ArcosSession session) {
    this.s = session;
    this.body = session.body;
  }

  void handle(ArRobotPacket p) {
    ArCommands command = ArCommands.fromNumber(p.getID());
    if (body.isSrisimCompat() && srisimCommand(p)) {
      return;
    }
    if (command == null) {
      ignored(p.getID(), IgnoredCommand.Reason.UNKNOWN);
      return;
    }
    if (body.profile() == SimProfile.MOBILESIM && MOBILESIM_IGNORES.contains(command)) {
      ignored(command, IgnoredCommand.Reason.NOT_IN_MOBILESIM);
      return;
    }
    MotionController m = body.motion();
    double heading = body.odometry().getTh();
    LaserModel laser = body.laser();
    LaserModel legacyLaser = laser != null && laser.acceptsLegacyCommands() ? laser : null;
    switch (command) {
      case PULSE, OPEN -> {} // PULSE only resets the watchdog; OPEN while open does nothing
      case CLOSE -> s.close();
      case POLLING -> body.sonar().polling(CommandCodec.readDataArg(p));
      case ENABLE -> m.enableMotors(intArg(p, 1) != 0);
      case SETA -> m.setTransAccel(intArg(p, 0));
      case SETV -> m.setTransVelMax(intArg(p, 0));
      case SETO -> seto(p);
      case MOVE -> m.move(intArg(p, 0));
      case ROTATE, RVEL -> m.setRotVel(intArg(p, 0));
      case SETRV -> m.setRotVelMax(intArg(p, 0));
      case VEL -> m.setVel(intArg(p, 0));
      case HEAD -> m.setHeading(intArg(p, 0));
      case DHEAD -> m.deltaHeading(intArg(p, 0), heading);
      case SAY -> body.io().say(CommandCodec.readDataArg(p));
      case JOYREQUEST -> s.joyMode = clampMode(intArg(p, 1));
      case CONFIG ->
          s.send(
              ServerPackets.config(
                  s.out(),
                  body,
                  s.host.sipCycleMillis(),
                  s.host.watchdogMillis(),
                  s.gyroCw,
                  s.gyroCcw));
      case ENCODER -> s.encoderMode = clampMode(intArg(p, 1));
      case SETRVDIR -> m.setRotVelMaxDir(intArg(p, 0));
      case DCHEAD -> m.deltaControlHeading(intArg(p, 0), heading);
      case SETRA -> m.setRotAccel(intArg(p, 0));
      case SONAR -> body.sonar().sonarCommand(intArg(p, 1));
      case STOP -> m.stop();
      case DIGOUT -> {
        int bits = bits16(p);
        body.io().digOut(bits >> 8, bits & 0xFF);
      }
      case VEL2 -> {
        int bits = bits16(p);
        double div = body.model().getVel2Divisor();
        m.setVel2((byte) (bits >> 8) * div, (byte) bits * div);
      }
      case GRIPPER -> {
        if (body.gripper() != null) {
          body.gripper().command(intArg(p, 0));
        } else {
          ignored(command, IgnoredCommand.Reason.NO_DEVICE);
        }
      }
      case ADSEL -> {
        if (srisimLaserStep(legacyLaser, p) == SrisimLaserSetup.Step.ARCOS) {
          body.io().selectAnalog(intArg(p, 0));
        }
      }
      case GRIPPERVAL -> {
        srisimLaserStep(legacyLaser, p); // 36 is also the gripper's value: it gets it either way
        if (body.gripper() != null) {
          body.gripper().setGripperVal(intArg(p, 0));
        } else if (legacyLaser == null) {
          ignored(command, IgnoredCommand.Reason.NO_DEVICE);
        }
      }
      case GRIPREQUEST -> {
        if (srisimLaserStep(legacyLaser, p) != SrisimLaserSetup.Step.ARCOS) {
          return;
        }
        if (body.profile() == SimProfile.MOBILESIM) {
          ignored(command, IgnoredCommand.Reason.NOT_IN_MOBILESIM);
        } else {
          s.gripMode = clampMode(intArg(p, 1)); // GRIPPERpac says "none" on a robot without
        }
      }
      case GYROCALCW -> {
        if (srisimLaserStep(legacyLaser, p) == SrisimLaserSetup.Step.ARCOS) {
          s.gyroCw = intArg(p, 0) & 0xFFFF;
        }
      }
      case GYROCALCCW -> s.gyroCcw = intArg(p, 0) & 0xFFFF;
      case IOREQUEST -> s.ioMode = clampMode(intArg(p, 1));
      case GETAUX -> auxRequest(1, intArg(p, 0));
      case GETAUX2 -> auxRequest(2, intArg(p, 0));
      case GETAUX3 -> auxRequest(3, intArg(p, 0));
      case TTY2 -> auxWrite(1, p);
      case TTY3 -> auxWrite(2, p);
      case TTY4 -> auxWrite(3, p);
      case BUMPSTALL -> body.setBumpStall(intArg(p, 0));
      case TCM2 -> tcm2(intArg(p, 1));
      case SONARCYCLE -> body.sonar().setCycle(intArg(p, 40));
      case E_STOP -> m.eStop();
      case GYRO -> {
        if (body.gyro() != null) {
          body.gyro().setStreaming(intArg(p, 1) != 0);
        } else {
          ignored(command, IgnoredCommand.Reason.NO_DEVICE);
        }
      }
      case REVCOUNT -> body.odometry().setRevCount(intArg(p, 0));
      case DRIFTFACTOR -> body.odometry().setDriftFactor(intArg(p, 0));
      case SOUNDTOG -> body.io().setSound(intArg(p, 1) != 0);
      case TICKSMM -> body.odometry().setTicksMm(intArg(p, 0));
      case SIM_SET_POSE -> simSetPose(p);
      case SIM_RESET -> body.resetToStart();
      case SIM_LRF_ENABLE -> {
        s.laserMode = laser != null ? clampMode(intArg(p, 1)) : 0;
        if (laser == null) {
          ignored(command, IgnoredCommand.Reason.NO_DEVICE);
        }
      }
      case SIM_LRF_SET_FOV_START, SIM_LRF_SET_FOV_END, SIM_LRF_SET_RES -> laserSetting(p, command);
      case SIM_CTRL -> simCtrl(p);
      case SIM_STAT -> simStat(intArg(p, 1));
      case SIM_MESSAGE ->
          log.info("{}: message from client: {}", body.name(), CommandCodec.readStringArg(p));
      case SIM_EXIT -> s.host.exitRequested(intArg(p, 0), body.name());
      case BATTEST -> body.io().batTest(intArg(p, 0));
      case RESET, MAINTENANCE -> {
        log.warn(
            "{}: client sent {} (controller reset); closing the session", body.name(), command);
        s.close();
      }
      // Accepted with nothing to simulate: a TCP link has no baud rate, and the LCD, charger, PID
      // gains, joystick drive, motor stall settings and battery information have no effect on the
      // simulated robot.
      case JOYDRIVE,
          HOSTBAUD,
          AUX1BAUD,
          AUX2BAUD,
          AUX3BAUD,
          M_STALL,
          LCDWRITE,
          BATTERYINFO,
          CHARGE,
          ROTKP,
          ROTKV,
          ROTKI,
          TRANSKP,
          TRANSKV,
          TRANSKI -> {}
      // Real ARCOS commands for hardware the simulator does not have.
      case DROTATE,
          PTUPOS,
          ARM_INFO,
          ARM_STATUS,
          ARM_INIT,
          ARM_CHECK,
          ARM_POWER,
          ARM_HOME,
          ARM_PARK,
          ARM_POS,
          ARM_SPEED,
          ARM_STOP,
          ARM_AUTOPARK,
          ARM_GRIPPARK ->
          ignored(command, IgnoredCommand.Reason.NOT_SIMULATED);
    }
  }

  private void ignored(ArCommands command, IgnoredCommand.Reason reason) {
    ignored(command.getNumber(), reason);
  }

  private void ignored(int command, IgnoredCommand.Reason reason) {
    s.host.ignoredCommand(command, reason, body.name());
  }

  /**
   * Commands 35–38 on a robot that takes SRISim's laser commands: a step of the laser set-up
   * sequence (applied all at once when it completes with 35), or an ARCOS command.
   */
  private SrisimLaserSetup.Step srisimLaserStep(LaserModel laser, ArRobotPacket p) {
    if (laser == null) {
      return SrisimLaserSetup.Step.ARCOS;
    }
    SrisimLaserSetup setup = laser.srisimSetup();
    SrisimLaserSetup.Step step = setup.accept(p.getID(), intArg(p, 0));
    if (step == SrisimLaserSetup.Step.APPLY) {
      laser.setStart(setup.start());
      laser.setEnd(setup.end());
      laser.setIncrement(setup.increment() / 100.0);
      s.laserMode = clampMode(intArg(p, 0));
    }
    return step;
  }

  /** SIM_LRF_SET_FOV_START/END and SIM_LRF_SET_RES: the laser's field of view and resolution. */
  private void laserSetting(ArRobotPacket p, ArCommands command) {
    LaserModel laser = body.laser();
    if (laser == null) {
      ignored(command, IgnoredCommand.Reason.NO_DEVICE);
      return;
    }
    switch (command) {
      case SIM_LRF_SET_FOV_START -> laser.setStart(intArg(p, -90));
      case SIM_LRF_SET_FOV_END -> laser.setEnd(intArg(p, 90));
      default -> laser.setIncrement(intArg(p, 100) / 100.0);
    }
  }

  /**
   * GETAUX, GETAUX2, GETAUX3: asks the port for {@code n} bytes (0 flushes); the SERAUXpac goes out
   * as soon as the port has them (at once, with no bytes, if nothing is attached).
   */
  private void auxRequest(int port, int n) {
    AuxPort aux = body.auxPort(port);
    aux.request(n);
    sendAuxAnswer(aux);
  }

  /** TTY2, TTY3, TTY4: the argument's bytes go out of the port to its device. */
  private void auxWrite(int port, ArRobotPacket p) {
    AuxPort aux = body.auxPort(port);
    aux.write(CommandCodec.readDataArg(p));
    sendAuxAnswer(aux);
  }

  private void sendAuxAnswer(AuxPort aux) {
    byte[] answer = aux.takeAnswer();
    if (answer != null) {
      s.send(new SerAuxPacket(aux.number(), answer).encode(s.out()));
    }
  }

  /**
   * SRISim's old commands (MobileSim's {@code --srisim-compat}): 62 ends the simulator, 66 and 67
   * set the true x and y (mm), 69 returns the robot to its start. Returns whether {@code p} was
   * one.
   */
  private boolean srisimCommand(ArRobotPacket p) {
    switch (p.getID()) {
      case 62 -> s.host.exitRequested(0, body.name());
      case 66 -> {
        ArPose t = body.getTruePose();
        body.setTruePose(new ArPose(intArg(p, 0), t.y(), t.th()));
      }
      case 67 -> {
        ArPose t = body.getTruePose();
        body.setTruePose(new ArPose(t.x(), intArg(p, 0), t.th()));
      }
      case 69 -> body.resetToStart();
      default -> {
        return false;
      }
    }
    return true;
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
        s.host.loadMapRequested(new String(raw, 0, end, StandardCharsets.ISO_8859_1), body.index());
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
      default -> s.drops().drop(DropReason.MALFORMED, "TCM2 mode " + mode + " (0..7)");
    }
  }
}
