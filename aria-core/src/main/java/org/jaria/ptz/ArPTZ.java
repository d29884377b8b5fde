package org.jaria.ptz;

import java.io.IOException;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.protocol.ArCommands;
import org.jaria.robot.ArRobot;

/**
 * A pan-tilt(-zoom) unit (ARIA's {@code ArPTZ}): commands go out of the robot's AUX1 port (the TTY2
 * command carries their bytes) or, if a connection is set with {@link #setDeviceConnection},
 * straight to that serial port. Angles are degrees, clamped to the unit's limits; the last
 * commanded position is remembered (these units are not asked where they are).
 */
public abstract class ArPTZ {

  private final ArRobot robot;
  private volatile ArDeviceConnection connection;
  private volatile double pan;
  private volatile double tilt;
  private volatile int zoom;

  /** A unit on {@code robot}'s AUX1 port (robot may be null if a connection is set). */
  protected ArPTZ(ArRobot robot) {
    this.robot = robot;
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
