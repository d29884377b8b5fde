package org.jaria.acts.ptz;

import java.util.function.Consumer;
import org.jaria.protocol.ArCommands;
import org.jaria.robot.ArRobot;

/**
 * The Canon VC-C4 / VC-C50i pan-tilt-zoom camera (ARIA's {@code ArVCC4}), the camera of the
 * thesis's colour-following example. Each request is encoded by {@link VCC4Packets} and handed, as
 * one command frame, to a sink: on a Pioneer the sink sends it through the microcontroller's AUX
 * serial port (ARIA's TTY2 command); in tests the sink records it.
 *
 * <p>This class talks one way, like ARIA's unidirectional mode: the getters report the last
 * position requested. The camera ignores a command that arrives while it is still busy with the
 * previous one, so frames must be paced: {@link #ArVCC4(ArRobot)} (ARIA's form) sends them through
 * the robot's AUX port at most one per 300 ms, the newest position replacing a queued one ({@link
 * PacedFrameSink}); with a plain sink the caller paces. Limits, from ARIA: pan ±98°, tilt
 * −30°..+88°, zoom 0..1960, pan speed 1..90°/s, tilt speed 1..69°/s.
 *
 * <p>Thread-safe.
 */
public class ArVCC4 implements ArPTZ {

  /** The VC-C4's movement limits. */
  public static final PtzLimits LIMITS = new PtzLimits(98, -98, 88, -30, 1960, 0);

  /** Fastest pan speed, degrees per second. */
  public static final double MAX_PAN_SLEW = 90;

  /** Fastest tilt speed, degrees per second. */
  public static final double MAX_TILT_SLEW = 69;

  /** Slowest pan or tilt speed, degrees per second. */
  public static final double MIN_SLEW = 1;

  private final Consumer<byte[]> sink;
  private final boolean inverted;
  private double pan;
  private double tilt;
  private int zoom;
  private double panSlew = MAX_PAN_SLEW;
  private double tiltSlew = MAX_TILT_SLEW;
  private boolean power;

  /**
   * A camera on {@code robot}'s AUX serial port (ARIA's {@code ArVCC4(&robot)}): frames go out with
   * the TTY2 command, paced at one per 300 ms by a task on the robot's cycle.
   */
  public ArVCC4(ArRobot robot) {
    this(pacedOn(robot), false);
  }

  private static Consumer<byte[]> pacedOn(ArRobot robot) {
    PacedFrameSink paced =
        new PacedFrameSink(
            frame -> robot.comDataN(ArCommands.TTY2, frame),
            robot.getClock(),
            PacedFrameSink.DEFAULT_INTERVAL_MS);
    robot.addUserTask("vcc4 pacing", 60, paced::flush);
    return paced;
  }

  /** A camera whose command frames go to {@code sink}. */
  public ArVCC4(Consumer<byte[]> sink) {
    this(sink, false);
  }

  /**
   * A camera whose command frames go to {@code sink}.
   *
   * @param inverted the camera hangs upside down (as on a PeopleBot): pan and tilt signs flip
   */
  public ArVCC4(Consumer<byte[]> sink, boolean inverted) {
    if (sink == null) {
      throw new IllegalArgumentException("ArVCC4 needs a sink for its command frames");
    }
    this.sink = sink;
    this.inverted = inverted;
  }

  @Override
  public String getTypeName() {
    return "vcc4";
  }

  /**
   * ARIA's start-up sequence: power on, host control mode, pedestal initialise, fastest pan and
   * tilt speeds, the full tilt range; then the position is 0, 0 and zoom 0.
   */
  @Override
  public synchronized boolean init() {
    send(VCC4Packets.power(true));
    power = true;
    send(VCC4Packets.hostControlMode());
    send(VCC4Packets.pedestalInit());
    send(VCC4Packets.panSlew(panSlew));
    send(VCC4Packets.tiltSlew(tiltSlew));
    send(VCC4Packets.tiltRange(LIMITS.maxNegTilt(), LIMITS.maxPosTilt()));
    pan = 0;
    tilt = 0;
    zoom = 0;
    return true;
  }

  @Override
  public synchronized boolean power(boolean on) {
    send(VCC4Packets.power(on));
    power = on;
    return true;
  }

  /** Whether the last power request was "on". */
  public synchronized boolean getPower() {
    return power;
  }

  @Override
  public synchronized boolean panTilt(double panDegrees, double tiltDegrees) {
    pan = LIMITS.clampPan(panDegrees);
    tilt = LIMITS.clampTilt(tiltDegrees);
    send(inverted ? VCC4Packets.panTilt(-pan, -tilt) : VCC4Packets.panTilt(pan, tilt));
    return true;
  }

  @Override
  public boolean canZoom() {
    return true;
  }

  @Override
  public synchronized boolean zoom(int value) {
    zoom = LIMITS.clampZoom(value);
    send(VCC4Packets.zoom(zoom));
    return true;
  }

  /** Electronic zoom level 0..3 (1×, 2×, 4×, 8×), clamped. */
  public synchronized boolean digitalZoom(int level) {
    send(VCC4Packets.digitalZoom(Math.max(0, Math.min(3, level))));
    return true;
  }

  /** Stops pan and tilt movement. */
  public synchronized boolean haltPanTilt() {
    send(VCC4Packets.stopPanTilt());
    return true;
  }

  /** Stops zoom movement. */
  public synchronized boolean haltZoom() {
    send(VCC4Packets.stopZoom());
    return true;
  }

  /** Sets the pan speed in degrees per second (clamped to 1..90). */
  public synchronized boolean panSlew(double degreesPerSecond) {
    panSlew = Math.max(MIN_SLEW, Math.min(MAX_PAN_SLEW, degreesPerSecond));
    send(VCC4Packets.panSlew(panSlew));
    return true;
  }

  /** Sets the tilt speed in degrees per second (clamped to 1..69). */
  public synchronized boolean tiltSlew(double degreesPerSecond) {
    tiltSlew = Math.max(MIN_SLEW, Math.min(MAX_TILT_SLEW, degreesPerSecond));
    send(VCC4Packets.tiltSlew(tiltSlew));
    return true;
  }

  /** The pan speed last set. */
  public synchronized double getPanSlew() {
    return panSlew;
  }

  /** The tilt speed last set. */
  public synchronized double getTiltSlew() {
    return tiltSlew;
  }

  /** Sets the front LED: 0 automatic, 1 green, 2 off, 3 red, 4 orange. */
  public synchronized void setLEDControlMode(int mode) {
    send(VCC4Packets.ledControl(mode));
  }

  @Override
  public synchronized double getPan() {
    return pan;
  }

  @Override
  public synchronized double getTilt() {
    return tilt;
  }

  @Override
  public synchronized int getZoom() {
    return zoom;
  }

  @Override
  public PtzLimits getLimits() {
    return LIMITS;
  }

  private void send(byte[] frame) {
    sink.accept(frame);
  }
}
