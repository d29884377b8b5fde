package org.jaria.sim;

import java.util.Locale;
import org.jaria.geom.ArPose;
import org.jaria.sim.serial.AuxDevices;

/**
 * What to put into a world with {@link SimWorld#addRobot(RobotOptions)}.
 *
 * @param subtype robot model, e.g. {@code p3dx-sh}, {@code p3at-sh}, {@code p2dx}, {@code amigo}
 * @param name the robot's name in logs and the API (null: model name and number)
 * @param startPose where it starts (null: the map's first RobotHome, else Dock, else the origin,
 *     moved aside until it touches nothing)
 * @param laser whether it carries a simulated laser (SIM_LRF_ENABLE streams 0x60/0x61 packets); by
 *     default the models MobileSim gives a laser carry one ({@link RobotModels#carriesLaser})
 * @param gyro whether it carries a rate gyro (CONFIGpac HasGyro 1, GYROpac on request)
 * @param gripper whether it carries a gripper (CONFIGpac HasGripper 1)
 * @param port TCP port (-1: the world's base port plus the robot's number; 0: any free port)
 * @param legacyLaserCommands whether commands 35–38 set up the laser (enable, start angle, end
 *     angle, increment), the laser commands of the older SRISim simulator that ARIA's {@code
 *     ArSimulatedLaser} still sends, instead of their ARCOS meanings (ADSEL, GRIPPERVAL,
 *     GRIPREQUEST, GYROCALCW). On by default for a robot with a laser, as MobileSim's SRISim laser
 *     compatibility is (its {@code --no-srisim-laser-compat} turns it off); only for a robot with a
 *     laser.
 * @param srisimCompat whether the rest of SRISim's old commands work too (MobileSim's {@code
 *     --srisim-compat}): 62 ends the simulator, 66 and 67 set the true x and y, 69 moves the robot
 *     back to its start; off by default, when 62, 66 and 67 keep their ARCOS meanings.
 * @param ptzType the camera or pan-tilt unit on AUX1, by ARIA's {@code PTZType} names: {@code vcc4}
 *     (default), {@code sony}, {@code dpptu} or {@code none} (see {@link AuxDevices})
 */
public record RobotOptions(
    String subtype,
    String name,
    ArPose startPose,
    boolean laser,
    boolean gyro,
    boolean gripper,
    int port,
    boolean legacyLaserCommands,
    boolean srisimCompat,
    String ptzType) {

  /** Checks and normalises the values (the subtype is lower-cased). */
  public RobotOptions {
    if (subtype == null || subtype.isBlank()) {
      throw new IllegalArgumentException("a robot needs a model subtype such as p3dx-sh");
    }
    subtype = subtype.trim().toLowerCase(Locale.ROOT);
    if (port < -1 || port > 65535) {
      throw new IllegalArgumentException("port must be -1 (automatic) or 0..65535, was " + port);
    }
    ptzType = AuxDevices.normalize(ptzType);
    if (legacyLaserCommands && !laser) {
      throw new IllegalArgumentException(
          "legacy laser commands need a laser: add withLaser(true) (or --laser) first");
    }
  }

  /**
   * A robot of {@code subtype} with a gripper, no gyro, default start and port, and a laser (with
   * the SRISim laser commands) if MobileSim's model of it carries one.
   */
  public static RobotOptions of(String subtype) {
    boolean laser = subtype != null && RobotModels.carriesLaser(subtype);
    return new RobotOptions(subtype, null, null, laser, false, true, -1, laser, false, "vcc4");
  }

  /** These options with another name. */
  public RobotOptions withName(String n) {
    return new RobotOptions(
        subtype,
        n,
        startPose,
        laser,
        gyro,
        gripper,
        port,
        legacyLaserCommands,
        srisimCompat,
        ptzType);
  }

  /** These options with another start pose. */
  public RobotOptions withStartPose(ArPose p) {
    return new RobotOptions(
        subtype, name, p, laser, gyro, gripper, port, legacyLaserCommands, srisimCompat, ptzType);
  }

  /**
   * These options with or without a laser. Adding a laser also turns on the SRISim laser commands
   * (as MobileSim does by default); removing it turns them off.
   */
  public RobotOptions withLaser(boolean on) {
    boolean legacy = on && (laser ? legacyLaserCommands : true);
    return new RobotOptions(
        subtype, name, startPose, on, gyro, gripper, port, legacy, srisimCompat, ptzType);
  }

  /** These options with or without a gyro. */
  public RobotOptions withGyro(boolean on) {
    return new RobotOptions(
        subtype,
        name,
        startPose,
        laser,
        on,
        gripper,
        port,
        legacyLaserCommands,
        srisimCompat,
        ptzType);
  }

  /** These options with or without a gripper. */
  public RobotOptions withGripper(boolean on) {
    return new RobotOptions(
        subtype,
        name,
        startPose,
        laser,
        gyro,
        on,
        port,
        legacyLaserCommands,
        srisimCompat,
        ptzType);
  }

  /**
   * These options with another device on AUX1: {@code vcc4}, {@code sony}, {@code dpptu}, {@code
   * none}.
   */
  public RobotOptions withPtzType(String type) {
    return new RobotOptions(
        subtype,
        name,
        startPose,
        laser,
        gyro,
        gripper,
        port,
        legacyLaserCommands,
        srisimCompat,
        type);
  }

  /** These options with another TCP port. */
  public RobotOptions withPort(int p) {
    return new RobotOptions(
        subtype,
        name,
        startPose,
        laser,
        gyro,
        gripper,
        p,
        legacyLaserCommands,
        srisimCompat,
        ptzType);
  }

  /**
   * These options with commands 35–38 read as the SRISim laser set-up commands, or as ARCOS reads
   * them (see {@link #legacyLaserCommands()}); turning them on needs a laser.
   */
  public RobotOptions withLegacyLaserCommands(boolean on) {
    return new RobotOptions(
        subtype, name, startPose, laser, gyro, gripper, port, on, srisimCompat, ptzType);
  }

  /** These options with or without SRISim's other old commands (see {@link #srisimCompat()}). */
  public RobotOptions withSrisimCompat(boolean on) {
    return new RobotOptions(
        subtype, name, startPose, laser, gyro, gripper, port, legacyLaserCommands, on, ptzType);
  }
}
