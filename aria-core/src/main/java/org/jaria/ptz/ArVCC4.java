package org.jaria.ptz;

import java.util.function.Consumer;
import org.jaria.robot.ArRobot;

/**
 * The Canon VC-C4 / VC-C50i pan-tilt-zoom camera (ARIA's {@code ArVCC4}), the camera of the
 * thesis's colour-following example: pan ±98°, tilt −30°..+88°, zoom 0..1960, pan speed 1..90°/s,
 * tilt speed 1..69°/s (ARIA's limits). Each request is encoded by {@link VCC4Packets} and handed,
 * as one command frame, to a sink: on a Pioneer the sink sends it through the microcontroller's AUX
 * serial port (ARIA's TTY2 command); in tests the sink records it. Signs are {@link ArPTZ}'s (pan
 * positive to the right), which are also the camera's: Canon's manual encodes "pan right 90°" as
 * {@code +800} units.
 *
 * <p>This class talks one way, like ARIA's unidirectional mode: the getters report the last
 * position requested. The camera ignores a command that arrives while it is still busy with the
 * previous one, so frames must be paced: {@link #ArVCC4(ArRobot)} (ARIA's form) sends them through
 * the robot's AUX port (or the serial port set with {@link #setDeviceConnection}) at most one per
 * 300 ms, the newest position replacing a queued one ({@link PacedFrameSink}); with a plain sink
 * the caller paces.
 */
public class ArVCC4 extends ArPTZ {

  /** Largest pan either way, degrees. */
  public static final double MAX_PAN = 98;

  /** Largest tilt up, degrees. */
  public static final double MAX_TILT = 88;

  /** Largest tilt down, degrees (negative). */
  public static final double MIN_TILT = -30;

  /** Largest optical zoom position. */
  public static final int MAX_ZOOM = 1960;

  /** Fastest pan speed, degrees per second. */
  public static final double MAX_PAN_SLEW = 90;

  /** Fastest tilt speed, degrees per second. */
  public static final double MAX_TILT_SLEW = 69;

  /** Slowest pan or tilt speed, degrees per second. */
  public static final double MIN_SLEW = 1;

  private final Consumer<byte[]> sink;
  private final boolean inverted;
  private volatile double panSlew = MAX_PAN_SLEW;
  private volatile double tiltSlew = MAX_TILT_SLEW;
  private volatile boolean power;

  /**
   * A camera on {@code robot}'s AUX serial port (ARIA's {@code ArVCC4(&robot)}): frames go out with
   * the TTY2 command, paced at one per 300 ms by a task on the robot's cycle.
   */
  @SuppressWarnings("this-escape") // the pacing task only sends once the robot runs its cycle
  public ArVCC4(ArRobot robot) {
    super(requireRobot(robot));
    PacedFrameSink paced =
        new PacedFrameSink(this::send, robot.getClock(), PacedFrameSink.DEFAULT_INTERVAL_MS);
    robot.addUserTask("vcc4 pacing", 60, paced::flush);
    this.sink = paced;
    this.inverted = false;
  }

  private static ArRobot requireRobot(ArRobot robot) {
    if (robot == null) {
      throw new IllegalArgumentException(
          "ArVCC4(robot) needs a robot; without one, give a sink for the command frames");
    }
    return robot;
  }

  /** A camera whose command frames go to {@code sink}. */
  public ArVCC4(Consumer<byte[]> sink) {
    this(sink, false);
  }

  /**
   * A camera whose command frames go to {@code sink}.
   *
   * @param inverted the camera hangs upside down (as on a PeopleBot): pan and tilt signs flip on
   *     the wire, and the caller keeps its own angles
   */
  public ArVCC4(Consumer<byte[]> sink, boolean inverted) {
    super(null);
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
  public boolean init() {
    frame(VCC4Packets.power(true));
    power = true;
    frame(VCC4Packets.hostControlMode());
    frame(VCC4Packets.pedestalInit());
    frame(VCC4Packets.panSlew(panSlew));
    frame(VCC4Packets.tiltSlew(tiltSlew));
    frame(VCC4Packets.tiltRange(MIN_TILT, MAX_TILT));
    setCommanded(0, 0, 0);
    return true;
  }

  /** Switches the camera on or off. */
  public boolean power(boolean on) {
    frame(VCC4Packets.power(on));
    power = on;
    return true;
  }

  /** Whether the last power request was "on". */
  public boolean getPower() {
    return power;
  }

  @Override
  public double getMaxPan() {
    return MAX_PAN;
  }

  @Override
  public double getMaxTilt() {
    return MAX_TILT;
  }

  @Override
  public double getMaxNegTilt() {
    return MIN_TILT;
  }

  @Override
  public int getMaxZoom() {
    return MAX_ZOOM;
  }

  @Override
  protected boolean panTiltClamped(double panDeg, double tiltDeg) {
    frame(inverted ? VCC4Packets.panTilt(-panDeg, -tiltDeg) : VCC4Packets.panTilt(panDeg, tiltDeg));
    return true;
  }

  @Override
  protected boolean zoomClamped(int value) {
    frame(VCC4Packets.zoom(value));
    return true;
  }

  /** Electronic zoom level 0..3 (1×, 2×, 4×, 8×), clamped. */
  public boolean digitalZoom(int level) {
    frame(VCC4Packets.digitalZoom(Math.max(0, Math.min(3, level))));
    return true;
  }

  @Override
  public boolean haltPanTilt() {
    frame(VCC4Packets.stopPanTilt());
    return true;
  }

  @Override
  public boolean haltZoom() {
    frame(VCC4Packets.stopZoom());
    return true;
  }

  @Override
  public boolean canPanTiltSlew() {
    return true;
  }

  /** Sets the pan speed in degrees per second (clamped to 1..90). */
  @Override
  public boolean panSlew(double degreesPerSecond) {
    panSlew = Math.max(MIN_SLEW, Math.min(MAX_PAN_SLEW, degreesPerSecond));
    frame(VCC4Packets.panSlew(panSlew));
    return true;
  }

  /** Sets the tilt speed in degrees per second (clamped to 1..69). */
  @Override
  public boolean tiltSlew(double degreesPerSecond) {
    tiltSlew = Math.max(MIN_SLEW, Math.min(MAX_TILT_SLEW, degreesPerSecond));
    frame(VCC4Packets.tiltSlew(tiltSlew));
    return true;
  }

  /** The pan speed last set. */
  public double getPanSlew() {
    return panSlew;
  }

  /** The tilt speed last set. */
  public double getTiltSlew() {
    return tiltSlew;
  }

  /** Sets the front LED: 0 automatic, 1 green, 2 off, 3 red, 4 orange. */
  public void setLEDControlMode(int mode) {
    frame(VCC4Packets.ledControl(mode));
  }

  private void frame(byte[] f) {
    sink.accept(f);
  }
}
