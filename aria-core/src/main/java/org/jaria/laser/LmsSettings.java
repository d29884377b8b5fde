package org.jaria.laser;

import java.util.Locale;

/**
 * How an LMS-200 is set up (ARIA's {@code -laserDegrees}, {@code -laserIncrement}, {@code
 * -laserUnits}, {@code -laserReflectorBits}, {@code -laserBaud} choices), and the telegrams that
 * set it up.
 *
 * @param degrees field of view: 180 or 100 (centred on the laser's front)
 * @param increment degrees between readings: 1, 0.5, or 0.25 (0.25 only with 100°)
 * @param units "1mm", "1cm" or "10cm": the unit of the raw distances
 * @param reflectorBits 1, 2 or 3 bits of reflectance per reading (fewer bits, longer range)
 * @param baud serial rate to switch to after connecting: 9600, 19200 or 38400
 */
public record LmsSettings(
    int degrees, double increment, String units, int reflectorBits, int baud) {

  /** ARIA's defaults: 180° by 1°, mm units, 1 reflector bit, 38400 baud. */
  public static final LmsSettings DEFAULT = new LmsSettings(180, 1, "1mm", 1, 38400);

  /** The rate an LMS-200 talks at after power-up. */
  public static final int POWER_UP_BAUD = 9600;

  /** Checks against what the laser can do. */
  public LmsSettings {
    if (degrees != 180 && degrees != 100) {
      throw new IllegalArgumentException(
          "an LMS-200 scans 180 or 100 degrees, not " + degrees + " (use -laserDegrees 180)");
    }
    if (increment != 1 && increment != 0.5 && increment != 0.25) {
      throw new IllegalArgumentException(
          "an LMS-200 reads every 1, 0.5 or 0.25 degrees, not " + increment);
    }
    if (increment == 0.25 && degrees != 100) {
      throw new IllegalArgumentException("0.25 degree increments need -laserDegrees 100");
    }
    units = units.toLowerCase(Locale.ROOT);
    if (!units.equals("1mm") && !units.equals("1cm") && !units.equals("10cm")) {
      throw new IllegalArgumentException(
          "LMS units are 1mm, 1cm or 10cm, not '" + units + "' (use -laserUnits 1mm)");
    }
    if (reflectorBits < 1 || reflectorBits > 3) {
      throw new IllegalArgumentException(
          "an LMS-200 gives 1, 2 or 3 reflector bits, not " + reflectorBits);
    }
    if (baud != 9600 && baud != 19200 && baud != 38400) {
      throw new IllegalArgumentException(
          "an LMS-200 switches to 9600, 19200 or 38400 baud, not " + baud);
    }
  }

  /** Readings per scan (181 for 180° by 1°). */
  public int readingCount() {
    return (int) Math.round(degrees / increment) + 1;
  }

  /** Millimetres per raw distance unit. */
  public int unitMm() {
    return switch (units) {
      case "1cm" -> 10;
      case "10cm" -> 100;
      default -> 1;
    };
  }

  /** Farthest distance the raw readings can express, mm (also capped at the LMS's 80 m). */
  public double maxRangeMm() {
    return Math.min(80_000, (double) LmsScanData.distanceMask(reflectorBits) * unitMm());
  }

  /** Mode-change argument of the "switch baud rate" telegram for {@code rate}. */
  static int baudModeByte(int rate) {
    return switch (rate) {
      case 38400 -> 0x40;
      case 19200 -> 0x41;
      case 9600 -> 0x42;
      default -> throw new IllegalArgumentException("no LMS baud mode for " + rate);
    };
  }

  /** Command 0x20: change the operating mode (or the baud rate) to {@code mode}. */
  public static LmsTelegram modeChange(int mode, byte... extra) {
    byte[] d = new byte[1 + extra.length];
    d[0] = (byte) mode;
    System.arraycopy(extra, 0, d, 1, extra.length);
    return LmsTelegram.toLaser(LmsCommands.CHANGE_MODE, d);
  }

  /** The telegram that switches the laser's serial rate to {@code rate}. */
  public static LmsTelegram baudChange(int rate) {
    return modeChange(baudModeByte(rate));
  }

  /** Command 0x3B: field of view and increment (hundredths of a degree). */
  public LmsTelegram variant() {
    int inc = (int) Math.round(increment * 100);
    return LmsTelegram.toLaser(
        LmsCommands.VARIANT, (byte) degrees, (byte) (degrees >> 8), (byte) inc, (byte) (inc >> 8));
  }

  /**
   * Command 0x77: the configuration block, with the measuring mode (distance bits versus reflector
   * bits) and the distance unit; everything else at the values ARIA uses.
   */
  public LmsTelegram configuration() {
    byte[] d = new byte[33];
    // bytes 0-1 blanking 0; bytes 2-3 peak threshold 70; byte 4 fog correction 0
    d[2] = 70;
    d[5] = (byte) measuringMode(reflectorBits);
    d[6] = (byte) unitsByte(units);
    // byte 7 temporary field set, byte 8 subtractive fields: 0
    d[9] = 2; // multiple evaluation
    d[10] = 2; // restart
    // bytes 11..32: restart time, the three contours, evaluation modes, restart times: all 0
    return LmsTelegram.toLaser(LmsCommands.CONFIGURE, d);
  }

  /** The configuration block's measuring-mode byte for a number of reflector bits. */
  static int measuringMode(int bits) {
    return switch (bits) {
      case 2 -> 3;
      case 3 -> 1;
      default -> 5;
    };
  }

  /** The configuration block's unit byte. */
  static int unitsByte(String units) {
    return switch (units) {
      case "1cm" -> 0;
      case "10cm" -> 2;
      default -> 1;
    };
  }

  /** Reflector bits for a configuration block's measuring-mode byte (the emulator's side). */
  public static int reflectorBitsOfMode(int mode) {
    return switch (mode) {
      case 3 -> 2;
      case 1 -> 3;
      default -> 1;
    };
  }

  /** Units for a configuration block's unit byte (the emulator's side). */
  public static String unitsOfByte(int b) {
    return switch (b) {
      case 0 -> "1cm";
      case 2 -> "10cm";
      default -> "1mm";
    };
  }
}
