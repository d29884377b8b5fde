package org.jaria.ptz;

import java.io.IOException;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.protocol.ArCommands;
import org.jaria.robot.ArRobot;

/**
 * A pan-tilt(-zoom) unit (ARIA's {@code ArPTZ}): commands go out of the robot's AUX1 port (the TTY2
 * command carries their bytes) or, if a connection is set with {@link #setDeviceConnection},
 * straight to that serial port. Angles are degrees with ARIA's signs: <b>pan positive to the
 * right</b> (clockwise seen from above), tilt positive up; 0, 0 looks straight ahead. Requests are
 * clamped to the unit's limits ({@link #getMaxNegPan()}..{@link #getMaxPosPan()}, {@link
 * #getMaxNegTilt()}..{@link #getMaxPosTilt()}); the last commanded position is remembered. Through
 * the robot, the unit's answers come back as SERAUXpacs (see {@link #requestPosition()}): a unit
 * that can say where it points reports that in {@link #getReportedPan()} and the like.
 *
 * <p>Every unit follows the same signs: the Sony ({@link ArSonyPTZ}), the Directed Perception
 * ({@link ArDPPTU}) and the Canon VC-C4 ({@link ArVCC4}) drivers, the simulator's camera and the
 * guiServer's camera requests (PtzSignTest in the simulator checks them against each other).
 *
 * <p>Safe to call from several threads: each request goes out whole, and the getters report the
 * last one.
 */
public abstract class ArPTZ {

  private final ArRobot robot;
  private final AuxReplyPump pump;
  private volatile ArDeviceConnection connection;
  private volatile double reportedPan = Double.NaN;
  private volatile double reportedTilt = Double.NaN;
  private volatile int reportedZoom = -1;
  private volatile double pan;
  private volatile double tilt;
  private volatile int zoom;

  /** A unit on {@code robot}'s AUX1 port (robot may be null if a connection is set). */
  @SuppressWarnings("this-escape") // the pump calls back only once the robot delivers packets
  protected ArPTZ(ArRobot robot) {
    this.robot = robot;
    this.pump = robot == null ? null : new AuxReplyPump(robot, this::replyBytes);
  }

  /**
   * Says that the unit will answer {@code n} more bytes to what was just sent, so they are fetched
   * from the robot's AUX1 port (nothing happens on a direct serial connection).
   */
  protected void expectReply(int n) {
    if (pump != null && connection == null) {
      pump.expect(n);
    }
  }

  /** Forgets the answers still expected and empties the robot's AUX1 buffer. */
  public void flushReplies() {
    if (pump != null) {
      pump.flush();
    }
  }

  /** Bytes of answer still expected from the unit. */
  public int getRepliesOutstanding() {
    return pump == null ? 0 : pump.outstanding();
  }

  /** Bytes the unit has answered through the robot. */
  public long getReplyBytes() {
    return pump == null ? 0 : pump.bytesReceived();
  }

  /**
   * Takes the bytes of one SERAUXpac, in order (the robot's thread calls it). Units that answer
   * parse them here; the default ignores them.
   */
  protected void replyBytes(byte[] data) {}

  /**
   * Asks the unit where it points; the answer arrives later in {@link #getReportedPan()} and the
   * like. False if the unit cannot be asked or the request could not be sent.
   */
  public boolean requestPosition() {
    return false;
  }

  /** Records where the unit said it points (pan, tilt in degrees). */
  protected void setReportedPanTilt(double panDeg, double tiltDeg) {
    reportedPan = panDeg;
    reportedTilt = tiltDeg;
  }

  /** Records the zoom the unit reported. */
  protected void setReportedZoom(int z) {
    reportedZoom = z;
  }

  /** Whether the unit has said where it points. */
  public boolean canGetRealPanTilt() {
    return !Double.isNaN(reportedPan);
  }

  /** The pan the unit last reported, degrees (NaN before an answer). */
  public double getReportedPan() {
    return reportedPan;
  }

  /** The tilt the unit last reported, degrees (NaN before an answer). */
  public double getReportedTilt() {
    return reportedTilt;
  }

  /** The zoom the unit last reported (−1 before an answer). */
  public int getReportedZoom() {
    return reportedZoom;
  }

  /** Sends to this (open) serial connection instead of the robot's AUX port. */
  public void setDeviceConnection(ArDeviceConnection c) {
    connection = c;
  }

  /** Sends {@code bytes} to the unit; false if they could not be sent. */
  protected boolean send(byte[] bytes) {
    ArDeviceConnection c = connection;
    if (c != null) {
      try {
        c.write(bytes, 0, bytes.length);
        return true;
      } catch (IOException e) {
        return false;
      }
    }
    return robot != null && robot.comDataN(ArCommands.TTY2, bytes);
  }

  /** Sets the unit up (modes, addresses). */
  public abstract boolean init();

  /** Sets the unit up again (ARIA's {@code reset()}: the same as {@link #init()} by default). */
  public void reset() {
    init();
  }

  /** A short name of the kind of unit ({@code "sony"}, {@code "dpptu"}, {@code "vcc4"}). */
  public abstract String getTypeName();

  /** Largest pan angle, degrees (the smallest is its negative unless the unit says otherwise). */
  public abstract double getMaxPan();

  /** Largest tilt angle, degrees (the smallest is its negative unless the unit says otherwise). */
  public abstract double getMaxTilt();

  /** Largest pan to the right, degrees. */
  public double getMaxPosPan() {
    return getMaxPan();
  }

  /** Largest pan to the left, degrees (negative). */
  public double getMaxNegPan() {
    return -getMaxPan();
  }

  /** Largest tilt up, degrees. */
  public double getMaxPosTilt() {
    return getMaxTilt();
  }

  /** Largest tilt down, degrees (negative). */
  public double getMaxNegTilt() {
    return -getMaxTilt();
  }

  /** Largest zoom value (0 if the unit does not zoom). */
  public int getMaxZoom() {
    return 0;
  }

  /** Smallest zoom value. */
  public int getMinZoom() {
    return 0;
  }

  /** Whether the unit zooms. */
  public boolean canZoom() {
    return getMaxZoom() > getMinZoom();
  }

  /** Stops a pan or tilt under way; false if the unit cannot. */
  public boolean haltPanTilt() {
    return false;
  }

  /** Stops a zoom under way; false if the unit cannot. */
  public boolean haltZoom() {
    return false;
  }

  /** Whether the pan and tilt speeds can be set. */
  public boolean canPanTiltSlew() {
    return false;
  }

  /** Sets the pan speed, degrees per second; false if the unit cannot. */
  public boolean panSlew(double degreesPerSecond) {
    return false;
  }

  /** Sets the tilt speed, degrees per second; false if the unit cannot. */
  public boolean tiltSlew(double degreesPerSecond) {
    return false;
  }

  /**
   * Records a position the unit was set to without {@link #panTilt} or {@link #zoom} (by its
   * initialisation, say), so the getters report it.
   */
  protected void setCommanded(double panDeg, double tiltDeg, int zoomValue) {
    pan = panDeg;
    tilt = tiltDeg;
    zoom = zoomValue;
  }

  /** Sends a pan and tilt already clamped to the limits. */
  protected abstract boolean panTiltClamped(double panDeg, double tiltDeg);

  /** Sends a zoom already clamped to the limits. */
  protected boolean zoomClamped(int value) {
    return false;
  }

  /** Pans and tilts to absolute angles (clamped to the unit's limits). */
  public boolean panTilt(double panDeg, double tiltDeg) {
    double p = Math.max(getMaxNegPan(), Math.min(getMaxPosPan(), panDeg));
    double t = Math.max(getMaxNegTilt(), Math.min(getMaxPosTilt(), tiltDeg));
    if (!panTiltClamped(p, t)) {
      return false;
    }
    pan = p;
    tilt = t;
    return true;
  }

  /** Pans to an absolute angle. */
  public boolean pan(double deg) {
    return panTilt(deg, tilt);
  }

  /** Tilts to an absolute angle. */
  public boolean tilt(double deg) {
    return panTilt(pan, deg);
  }

  /** Pans by {@code deg} from the last commanded angle. */
  public boolean panRel(double deg) {
    return panTilt(pan + deg, tilt);
  }

  /** Tilts by {@code deg} from the last commanded angle. */
  public boolean tiltRel(double deg) {
    return panTilt(pan, tilt + deg);
  }

  /** Pans and tilts by {@code panDeg} and {@code tiltDeg} from the last commanded angles. */
  public boolean panTiltRel(double panDeg, double tiltDeg) {
    return panTilt(pan + panDeg, tilt + tiltDeg);
  }

  /** Zooms by {@code amount} from the last commanded zoom. */
  public boolean zoomRel(int amount) {
    return zoom(zoom + amount);
  }

  /** Zooms ({@link #getMinZoom()}..{@link #getMaxZoom()}). */
  public boolean zoom(int value) {
    int z = Math.max(getMinZoom(), Math.min(getMaxZoom(), value));
    if (!zoomClamped(z)) {
      return false;
    }
    zoom = z;
    return true;
  }

  /** The last commanded pan, degrees. */
  public double getPan() {
    return pan;
  }

  /** The last commanded tilt, degrees. */
  public double getTilt() {
    return tilt;
  }

  /** The last commanded zoom. */
  public int getZoom() {
    return zoom;
  }
}
