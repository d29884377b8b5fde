package org.jaria.ptz;

import java.io.IOException;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.protocol.ArCommands;
import org.jaria.robot.ArRobot;

/**
 * A pan-tilt(-zoom) unit (ARIA's {@code ArPTZ}): commands go out of the robot's AUX1 port (the TTY2
 * command carries their bytes) or, if a connection is set with {@link #setDeviceConnection},
 * straight to that serial port. Angles are degrees (pan positive to the right, tilt positive up, as
 * ARIA), clamped to the unit's limits; the last commanded position is remembered. Through the
 * robot, the unit's answers come back as SERAUXpacs (see {@link #requestPosition()}): a unit that
 * can say where it points reports that in {@link #getReportedPan()} and the like.
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

  /** Largest pan angle, degrees (the smallest is its negative). */
  public abstract double getMaxPan();

  /** Largest tilt angle, degrees (the smallest is its negative). */
  public abstract double getMaxTilt();

  /** Largest zoom value (0 if the unit does not zoom). */
  public int getMaxZoom() {
    return 0;
  }

  /** Sends a pan and tilt already clamped to the limits. */
  protected abstract boolean panTiltClamped(double panDeg, double tiltDeg);

  /** Sends a zoom already clamped to the limits. */
  protected boolean zoomClamped(int value) {
    return false;
  }

  /** Pans and tilts to absolute angles (clamped to the unit's limits). */
  public boolean panTilt(double panDeg, double tiltDeg) {
    double p = Math.max(-getMaxPan(), Math.min(getMaxPan(), panDeg));
    double t = Math.max(-getMaxTilt(), Math.min(getMaxTilt(), tiltDeg));
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

  /** Zooms (0..{@link #getMaxZoom()}). */
  public boolean zoom(int value) {
    int z = Math.max(0, Math.min(getMaxZoom(), value));
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
