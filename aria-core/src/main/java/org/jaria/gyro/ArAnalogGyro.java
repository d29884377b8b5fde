package org.jaria.gyro;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.protocol.packets.GyroPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.robot.ArListPos;
import org.jaria.robot.ArPacketHandler;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The robot's gyro (ARIA's {@code ArAnalogGyro}). Pioneers carry one of two kinds, told apart by
 * the {@code HasGyro} field of the CONFIGpac when connecting:
 *
 * <ul>
 *   <li><b>client-side</b> ({@code HasGyro} 1, {@link GyroType#GYRO_ANALOG_COMPUTER}): the robot
 *       streams raw rate samples in GYROpacs after GYRO 1; this class integrates them and fuses
 *       them with the wheels' odometry ({@link AnalogGyroFilter}), giving the heading change to use
 *       for each odometry update through {@link #correctedDeltaTh};
 *   <li><b>server-side</b> ({@code HasGyro} 2 or more, {@link GyroType#GYRO_ANALOG_CONTROLLER}):
 *       the controller corrects its own heading once GYRO 1 is sent, and the SIP heading is trusted
 *       as it is.
 * </ul>
 *
 * <p>Create it before or after connecting; it acts on every connection. For robots (or simulators)
 * that do not report their gyro, give the type explicitly.
 *
 * <pre>{@code
 * ArAnalogGyro gyro = new ArAnalogGyro(robot);
 * ...
 * System.out.printf("gyro %.1f robot %.1f%n", gyro.getHeading(), robot.getTh());
 * }</pre>
 *
 * <p>A client-side gyro corrects the robot's pose itself: the gyro installs {@link
 * #correctedDeltaTh} as the robot's encoder correction ({@code setEncoderCorrectionCallback}), so
 * every SIP's heading change comes from the fused gyro and wheels, and {@code robot.getTh()}
 * follows.
 *
 * <p>For simulators producing GYROpacs: a rotation of {@code w} deg/s (counter-clockwise positive)
 * reads {@code bias − w × 2.5 / 300 × 1023 / 5 / GyroScaler} counts, one sample every 25 ms.
 */
public class ArAnalogGyro implements AutoCloseable {

  /** Which gyro the robot has. */
  public enum GyroType {
    /** No gyro (or not known yet). */
    GYRO_NONE,
    /** Rate samples sent to the client, which does the correction. */
    GYRO_ANALOG_COMPUTER,
    /** The controller corrects its own heading. */
    GYRO_ANALOG_CONTROLLER
  }

  private static final Logger log = LoggerFactory.getLogger(ArAnalogGyro.class);
  private static final String TASK_NAME = "ArAnalogGyro";
  private static final int GYRO_FAULT_BIT = 1 << 4;

  private final ArRobot robot;
  private final GyroType forcedType;
  private final AnalogGyroFilter filter = new AnalogGyroFilter(0);
  private final ArPacketHandler packetHandler = this::handleGyroPacket;
  private final Runnable connectCb = this::connected;
  private final AtomicLong packets = new AtomicLong();
  private volatile GyroType gyroType = GyroType.GYRO_NONE;
  private volatile boolean active = true;
  private volatile boolean gyroOnlyActive;
  private volatile boolean haveGottenData;
  private volatile boolean gyroWorking = true;
  private long packetSecond = -1;
  private int pacCurrentCount;
  private volatile int pacCount;

  /** A gyro whose kind is read from the robot's CONFIGpac on each connection. */
  public ArAnalogGyro(ArRobot robot) {
    this(robot, null);
  }

  /**
   * A gyro of a known kind (for robots or simulators that do not report it); {@code null} reads it
   * from the CONFIGpac.
   */
  public ArAnalogGyro(ArRobot robot, GyroType type) {
    this.robot = robot;
    this.forcedType = type;
    robot.addPacketHandler(packetHandler, ArListPos.LAST);
    robot.addConnectCB(connectCb);
    robot.addUserTask(TASK_NAME, 50, this::userTask);
    if (robot.isConnected()) {
      connected();
    }
  }

  private void connected() {
    GyroType t = forcedType;
    if (t == null) {
      ArConfigPacket config = robot.getOrigRobotConfig();
      int hasGyro = config == null ? 0 : config.getHasGyro();
      t =
          hasGyro == 1
              ? GyroType.GYRO_ANALOG_COMPUTER
              : hasGyro >= 2 ? GyroType.GYRO_ANALOG_CONTROLLER : GyroType.GYRO_NONE;
    }
    gyroType = t;
    switch (t) {
      case GYRO_ANALOG_COMPUTER -> {
        haveGottenData = false;
        filter.setScalingFactor(robot.getRobotParams().getGyroScaler());
        log.info("client-side gyro, scaler {}", filter.getScalingFactor());
        robot.setEncoderCorrectionCallback(this::correctedDeltaTh);
        robot.comInt(ArCommands.GYRO, 1);
      }
      case GYRO_ANALOG_CONTROLLER -> {
        haveGottenData = true;
        log.info("controller gyro");
        if (active || gyroOnlyActive) {
          robot.comInt(ArCommands.GYRO, gyroOnlyActive ? 2 : 1);
        }
      }
      case GYRO_NONE -> log.debug("the robot reports no gyro");
    }
  }

  /** Takes GYROpacs: integrates their samples. Returns whether the packet was one. */
  boolean handleGyroPacket(ArRobotPacket packet) {
    if (packet.getID() != PacketIds.GYRO) {
      return false;
    }
    GyroPacket g = GyroPacket.decode(packet);
    if (g == null) {
      log.debug("malformed GYROpac ignored");
      return true;
    }
    long now = robot.getClock().nanoTime();
    if (g.size() > 0) {
      haveGottenData = true;
    }
    double vel = robot.getVel();
    double rotVel = robot.getRotVel();
    int[] temps = g.temperatures();
    for (int i = 0; i < g.size(); i++) {
      filter.addReading(g.rate(i), temps[i], vel, rotVel, now);
    }
    packets.incrementAndGet();
    countPacket(now);
    return true;
  }

  private synchronized void countPacket(long now) {
    long second = TimeUnit.NANOSECONDS.toSeconds(now);
    if (second != packetSecond) {
      packetSecond = second;
      pacCount = pacCurrentCount;
      pacCurrentCount = 0;
    }
    pacCurrentCount++;
  }

  private void userTask() {
    boolean failed = (robot.getFaultFlags() & GYRO_FAULT_BIT) != 0;
    if (failed && gyroWorking) {
      log.warn("ArAnalogGyro: gyro failed");
      gyroWorking = false;
    } else if (!failed && !gyroWorking) {
      log.info("ArAnalogGyro: gyro recovered");
      gyroWorking = true;
    }
  }

  /**
   * The change of heading to use for one odometry update, degrees: fused with the gyro for a
   * client-side gyro that is active, the wheels' own otherwise. Matches the robot's heading
   * correction hook, so {@code gyro::correctedDeltaTh} can be plugged in.
   */
  public double correctedDeltaTh(double deltaX, double deltaY, double deltaTh, long timeNanos) {
    if (gyroType != GyroType.GYRO_ANALOG_COMPUTER) {
      return deltaTh;
    }
    return filter.correctedDeltaTh(deltaX, deltaY, deltaTh, timeNanos);
  }

  /** The heading integrated from the gyro alone (client-side gyro), degrees. */
  public double getHeading() {
    return filter.getHeading();
  }

  /** The gyro's last temperature byte. */
  public int getTemperature() {
    return filter.getTemperature();
  }

  /** The gyro's bias, the mean reading at rest (0 until known). */
  public double getAverage() {
    return filter.getAverage();
  }

  /** The filter doing the arithmetic. */
  public AnalogGyroFilter getFilter() {
    return filter;
  }

  /** The kind of gyro in use. */
  public GyroType getGyroType() {
    return gyroType;
  }

  /** Whether the gyro can run alone, without the wheels (controller gyros). */
  public boolean hasGyroOnlyMode() {
    return gyroType == GyroType.GYRO_ANALOG_CONTROLLER;
  }

  /** Whether gyro data has arrived (always true for controller gyros). */
  public boolean haveGottenData() {
    return haveGottenData;
  }

  /** Whether the controller reports the gyro working (fault flag bit 4 clear). */
  public boolean isGyroWorking() {
    return gyroWorking;
  }

  /** GYROpacs received in the last whole second. */
  public int getPacCount() {
    return pacCount;
  }

  /** GYROpacs received since creation. */
  public long getPacketsReceived() {
    return packets.get();
  }

  /** Uses the gyro to correct the heading. */
  public void activate() {
    active = true;
    gyroOnlyActive = false;
    filter.setActive(true);
    if (gyroType == GyroType.GYRO_ANALOG_CONTROLLER) {
      robot.comInt(ArCommands.GYRO, 1);
    }
  }

  /** Stops using the gyro (the wheels alone give the heading). */
  public void deactivate() {
    active = false;
    gyroOnlyActive = false;
    filter.setActive(false);
    if (gyroType == GyroType.GYRO_ANALOG_CONTROLLER) {
      robot.comInt(ArCommands.GYRO, 0);
    }
  }

  /**
   * Uses the gyro alone for heading (controller gyros only).
   *
   * @return false if this gyro cannot do that
   */
  public boolean activateGyroOnly() {
    if (!hasGyroOnlyMode()) {
      log.info("gyro-only mode rejected: this gyro cannot do it");
      return false;
    }
    active = false;
    gyroOnlyActive = true;
    robot.comInt(ArCommands.GYRO, 2);
    return true;
  }

  /** Whether the gyro corrects the heading. */
  public boolean isActive() {
    return active;
  }

  /** Whether the gyro alone gives the heading. */
  public boolean isGyroOnlyActive() {
    return gyroOnlyActive;
  }

  /** Turns the gyro stream off (GYRO 0 when connected) and detaches from the robot. */
  @Override
  public void close() {
    if (robot.isConnected() && gyroType != GyroType.GYRO_NONE) {
      robot.comInt(ArCommands.GYRO, 0);
    }
    if (gyroType == GyroType.GYRO_ANALOG_COMPUTER) {
      robot.setEncoderCorrectionCallback(null);
    }
    robot.remPacketHandler(packetHandler);
    robot.remConnectCB(connectCb);
    robot.remUserTask(TASK_NAME);
  }
}
