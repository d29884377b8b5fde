package org.jaria.sim.robot;

import java.util.Arrays;

/**
 * The controller's user I/O and housekeeping values: digital inputs and outputs, the analog ports
 * (ADSEL picks the one reported in the SIP), the battery, the buzzer and the compass mode.
 *
 * <p>Not thread-safe: used by the world thread.
 */
public final class RobotIo {

  /** Nominal battery voltage, decivolts. */
  public static final int NOMINAL_BATTERY = 130;

  /** Analog ports reported in IOpac (the battery analog follows them). */
  public static final int ANALOG_PORTS = 8;

  private int digIn;
  private int digOut;
  private final int digOutAtOpen;
  private final int[] analog = new int[ANALOG_PORTS];
  private int anPort;
  private int batteryOverride;
  private boolean soundOn = true;
  private byte[] lastSay = new byte[0];
  private int compassMode;

  /** I/O with all digital inputs and outputs low (a real Pioneer's at power-on). */
  public RobotIo() {
    this(0, 0);
  }

  /**
   * I/O whose digital inputs read {@code digIn} until set, and whose outputs start at {@code
   * digOutAtOpen} with every session (MobileSim reports 0xFF for both).
   */
  public RobotIo(int digIn, int digOutAtOpen) {
    this.digIn = digIn & 0xFF;
    this.digOutAtOpen = digOutAtOpen & 0xFF;
    this.digOut = this.digOutAtOpen;
  }

  /** Returns the session settings to their defaults (digital inputs and analogs are physical). */
  public void resetSettings() {
    digOut = digOutAtOpen;
    anPort = 0;
    soundOn = true;
    compassMode = 0;
  }

  /** DIGOUT: bits set in {@code mask} take the value of the same bit of {@code states}. */
  public void digOut(int mask, int states) {
    digOut = ((digOut & ~mask) | (states & mask)) & 0xFF;
  }

  /** Digital outputs. */
  public int getDigOut() {
    return digOut;
  }

  /** Digital inputs (set from outside the robot: the API). */
  public void setDigIn(int bits) {
    digIn = bits & 0xFF;
  }

  /** Digital inputs. */
  public int getDigIn() {
    return digIn;
  }

  /** Sets analog port {@code port} (0..7) to {@code value} (0..1023 for 0..5 V). */
  public void setAnalog(int port, int value) {
    analog[port] = Math.max(0, Math.min(1023, value));
  }

  /** Analog port {@code port}, 0..1023. */
  public int getAnalog(int port) {
    return analog[port];
  }

  /** All analog ports. */
  public int[] analogs() {
    return Arrays.copyOf(analog, ANALOG_PORTS);
  }

  /** ADSEL: selects the analog port reported in the SIP. */
  public void selectAnalog(int port) {
    anPort = port & 0xFF;
  }

  /** Selected analog port. */
  public int getAnPort() {
    return anPort;
  }

  /** The selected analog port scaled to a byte (0..255 = 0..5 V), as in the SIP. */
  public int selectedAnalogByte() {
    return anPort < ANALOG_PORTS ? analog[anPort] >> 2 : 0;
  }

  /** BATTEST: pretend the battery is at {@code decivolts}; 0 returns to the real value. */
  public void batTest(int decivolts) {
    batteryOverride = Math.max(0, decivolts);
  }

  /** Battery voltage, decivolts. */
  public int getBattery() {
    return batteryOverride > 0 ? batteryOverride : NOMINAL_BATTERY;
  }

  /** The battery analog of IOpac (0..1023), the voltage through a 1/3 divider on a 5 V scale. */
  public int batteryAnalog() {
    return Math.min(1023, (int) Math.round(getBattery() / 10.0 / 3 / 5 * 1023));
  }

  /** SOUNDTOG: buzzer on or off. */
  public void setSound(boolean on) {
    soundOn = on;
  }

  /** Whether the buzzer is on. */
  public boolean isSoundOn() {
    return soundOn;
  }

  /** SAY: the (duration, tone) byte pairs last played. */
  public void say(byte[] pairs) {
    lastSay = pairs.clone();
  }

  /** The last SAY argument. */
  public byte[] getLastSay() {
    return lastSay.clone();
  }

  /** TCM2 mode: 0 off, 1 compass in the SIP, 3 continuous TCM2pac... */
  public void setCompassMode(int mode) {
    compassMode = mode;
  }

  /** TCM2 mode. */
  public int getCompassMode() {
    return compassMode;
  }
}
