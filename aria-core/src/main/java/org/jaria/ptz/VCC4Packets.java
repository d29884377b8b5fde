package org.jaria.ptz;

import java.io.ByteArrayOutputStream;
import java.util.Locale;
import org.jaria.geom.ArMath;

/**
 * Byte-level encoder of Canon VC-C4 / VC-C50i camera commands, exactly as they go over the serial
 * line (on a Pioneer, through the microcontroller's AUX port with the TTY2 command).
 *
 * <p>Every command frame is {@code FF 30 30 00 <command> <parameters> EF}: header {@code FF},
 * device number {@code 30}, camera address {@code 30} (the first camera of a chain), {@code 00},
 * the command byte, its parameters, and the end mark {@code EF}. Numeric parameters are sent as
 * upper-case ASCII hexadecimal digits. Pan and tilt positions are in units of 0.1125° offset by
 * {@code 0x8000} (so 0° is {@code "8000"}), rounded half away from zero.
 *
 * <p>Sources relied on (the tests check the byte arrays against their worked examples):
 *
 * <ul>
 *   <li>Canon VC-C50i/VC-C50iR Programmer's Manual (same command set as the VC-C4): §12.11 Pedestal
 *       Initialize 1 ({@code FF 30 30 00 58 30 EF}), §12.5 Pan/Tilt Stop ({@code 53 30}), Pan/Tilt
 *       Angle Assignment {@code 62} with the example "pan right 90 degrees, tilt lower 30 degrees"
 *       = {@code 8320h}, {@code 7EF5h}, §13.2 Camera ON ({@code A0 31}), §13.18 Zoom Position 2
 *       Assignment {@code B3} (example 256 = {@code 30 31 30 30}), §13.55 Electronic Zoom {@code
 *       B7}, §14.26 LED Forced Control {@code 8E}, §16.2's initial-setting frame list; pages at
 *       manualsdir.com/manuals/459376 (Vaddio Canon VC-C50i Programmer's manual) and
 *       manualslib.com/manual/415278.
 *   <li>ARIA's {@code ArVCC4.cpp} / {@code ArVCC4.h} (MobileRobots; read for the command bytes and
 *       parameter formats it sends: host control mode {@code 90 30}, pan/tilt speed {@code 50} /
 *       {@code 51} with 3 hex digits, tilt range assignment {@code 64 31}, zoom stop {@code A2 30},
 *       position requests {@code 63} and {@code B4 30}, and its limits).
 * </ul>
 */
public final class VCC4Packets {

  /** Degrees per pan/tilt position unit. */
  public static final double DEGREES_PER_UNIT = 0.1125;

  /** Frame header byte. */
  public static final int HEADER = 0xFF;

  /** Device number (and the default camera address). */
  public static final int DEVICE_ID = 0x30;

  /** Frame end mark. */
  public static final int FOOTER = 0xEF;

  /** Header of a camera answer. */
  public static final int RESPONSE = 0xFE;

  /** Pan speed assignment. */
  public static final int PAN_SLEW = 0x50;

  /** Tilt speed assignment. */
  public static final int TILT_SLEW = 0x51;

  /** Pan/tilt stop. */
  public static final int STOP = 0x53;

  /** Pedestal initialise. */
  public static final int INIT = 0x58;

  /** Pan/tilt angle assignment. */
  public static final int PAN_TILT = 0x62;

  /** Pan/tilt position request. */
  public static final int PAN_TILT_REQUEST = 0x63;

  /** Pan/tilt movable range assignment. */
  public static final int SET_RANGE = 0x64;

  /** LED forced control. */
  public static final int LED_CONTROL = 0x8E;

  /** Host/local control mode. */
  public static final int CONTROL = 0x90;

  /** Camera power on/off. */
  public static final int POWER = 0xA0;

  /** Zoom stop (and zoom start commands). */
  public static final int ZOOM_STOP = 0xA2;

  /** Zoom position assignment (0..0x7A8). */
  public static final int ZOOM = 0xB3;

  /** Zoom position request. */
  public static final int ZOOM_REQUEST = 0xB4;

  /** Electronic (digital) zoom setting. */
  public static final int DIGITAL_ZOOM = 0xB7;

  private VCC4Packets() {}

  /** Camera power on ({@code A0 31}) or off ({@code A0 30}). */
  public static byte[] power(boolean on) {
    return frame(POWER, on ? 0x31 : 0x30);
  }

  /** Host control mode: the camera obeys the serial line ({@code 90 30}). */
  public static byte[] hostControlMode() {
    return frame(CONTROL, 0x30);
  }

  /** Pedestal initialise 1: find the home position and go there ({@code 58 30}). */
  public static byte[] pedestalInit() {
    return frame(INIT, 0x30);
  }

  /** Pan/tilt to absolute angles in degrees ({@code 62} + 4 + 4 hex digits). */
  public static byte[] panTilt(double panDegrees, double tiltDegrees) {
    return frame(PAN_TILT, hex(units(panDegrees), 4) + hex(units(tiltDegrees), 4));
  }

  /** Stops pan and tilt movement ({@code 53 30}). */
  public static byte[] stopPanTilt() {
    return frame(STOP, 0x30);
  }

  /** Zoom to a position 0..1960 ({@code B3} + 4 hex digits). */
  public static byte[] zoom(int position) {
    if (position < 0 || position > 0xFFFF) {
      throw new IllegalArgumentException("zoom position must be 0..65535, got " + position);
    }
    return frame(ZOOM, hex(position, 4));
  }

  /** Stops zoom movement ({@code A2 30}). */
  public static byte[] stopZoom() {
    return frame(ZOOM_STOP, 0x30);
  }

  /** Pan speed in degrees per second ({@code 50} + 3 hex digits of 0.1125°/s units). */
  public static byte[] panSlew(double degreesPerSecond) {
    return frame(PAN_SLEW, hex(ArMath.roundInt(degreesPerSecond / DEGREES_PER_UNIT), 3));
  }

  /** Tilt speed in degrees per second ({@code 51} + 3 hex digits). */
  public static byte[] tiltSlew(double degreesPerSecond) {
    return frame(TILT_SLEW, hex(ArMath.roundInt(degreesPerSecond / DEGREES_PER_UNIT), 3));
  }

  /**
   * The tilt movable range ({@code 64 31} + min + max, 4 hex digits each); the camera's default
   * upper limit is lower than the pedestal can reach, so ARIA widens it at start-up.
   */
  public static byte[] tiltRange(double minDegrees, double maxDegrees) {
    return frame(SET_RANGE, "1" + hex(units(minDegrees), 4) + hex(units(maxDegrees), 4));
  }

  /** Electronic zoom: level 0..3 for 1×, 2×, 4×, 8× ({@code B7 30 3X}). */
  public static byte[] digitalZoom(int level) {
    if (level < 0 || level > 3) {
      throw new IllegalArgumentException("digital zoom level must be 0..3 (1x..8x), got " + level);
    }
    return frame(DIGITAL_ZOOM, hex(1 << level, 2));
  }

  /** LED control: 0 auto, 1 green, 2 all off, 3 red, 4 orange ({@code 8E 3X}). */
  public static byte[] ledControl(int mode) {
    if (mode < 0 || mode > 4) {
      throw new IllegalArgumentException("LED mode must be 0..4, got " + mode);
    }
    return frame(LED_CONTROL, 0x30 + mode);
  }

  /** Asks for the real pan/tilt position ({@code 63}). */
  public static byte[] requestPanTilt() {
    return frame(PAN_TILT_REQUEST, "");
  }

  /** Asks for the real zoom position ({@code B4 30}). */
  public static byte[] requestZoom() {
    return frame(ZOOM_REQUEST, 0x30);
  }

  /** Camera position units ({@code 0x8000} = 0°) for an angle. */
  public static int units(double degrees) {
    return ArMath.roundInt(degrees / DEGREES_PER_UNIT) + 0x8000;
  }

  /** The frames as text, e.g. {@code "FF 30 30 00 58 30 EF"} (for logs and tests). */
  public static String toHex(byte[] frame) {
    StringBuilder b = new StringBuilder();
    for (byte x : frame) {
      if (b.length() > 0) {
        b.append(' ');
      }
      b.append(String.format(Locale.ROOT, "%02X", x & 0xFF));
    }
    return b.toString();
  }

  private static String hex(int value, int digits) {
    String s = Integer.toHexString(value).toUpperCase(Locale.ROOT);
    if (s.length() > digits || value < 0) {
      throw new IllegalArgumentException(value + " does not fit in " + digits + " hex digits");
    }
    return "0".repeat(digits - s.length()) + s;
  }

  private static byte[] frame(int command, int parameter) {
    return build(command, new byte[] {(byte) parameter});
  }

  private static byte[] frame(int command, String asciiParameters) {
    byte[] p = new byte[asciiParameters.length()];
    for (int i = 0; i < p.length; i++) {
      p[i] = (byte) asciiParameters.charAt(i);
    }
    return build(command, p);
  }

  private static byte[] build(int command, byte[] parameters) {
    ByteArrayOutputStream out = new ByteArrayOutputStream(6 + parameters.length);
    out.write(HEADER);
    out.write(DEVICE_ID);
    out.write(DEVICE_ID);
    out.write(0x00);
    out.write(command);
    out.write(parameters, 0, parameters.length);
    out.write(FOOTER);
    return out.toByteArray();
  }
}
