package org.jaria.input;

import java.util.Arrays;

/**
 * A joystick's state, fed from values (ARIA's {@code ArJoyHandler}). Reading a real desktop
 * joystick is outside the library: whatever reads one (a GUI toolkit, a game-controller library, a
 * network client) calls {@link #setAxes}/{@link #setButton}, and {@link
 * org.jaria.action.ArActionJoydrive} reads the result.
 *
 * <p>As in ARIA, raw axis values run from −128 to 128 with x positive to the right and y positive
 * forward, axes and buttons are numbered from 1, and there are two ways of calibrating: trusting
 * the values as already calibrated ("OS calibration", the default), or tracking the centre, minimum
 * and maximum of each axis ({@link #startCal()}, {@link #endCal()}, and every value seen widens the
 * range).
 *
 * <p>Thread-safe: one thread may feed values while another reads them.
 */
public class ArJoyHandler {

  /** Integer x, y, z values. */
  public record JoyVec3i(int x, int y, int z) {}

  /** Floating-point x, y, z values. */
  public record JoyVec3f(double x, double y, double z) {}

  private static final int MAX_AXES = 8;
  private static final int MAX_BUTTONS = 16;

  private final int[] axes = new int[MAX_AXES + 1];
  private final boolean[] buttons = new boolean[MAX_BUTTONS + 1];
  private boolean useOSCal;
  private boolean haveJoystick;
  private int numAxes;
  private int numButtons;
  private int topX = 100;
  private int topY = 100;
  private int topZ = 100;
  private int maxX;
  private int minX;
  private int maxY;
  private int minY;
  private int cenX;
  private int cenY;

  /** A handler using "OS calibration", without a joystick until one is {@link #connect}ed. */
  public ArJoyHandler() {
    this(true);
  }

  /** A handler with the given calibration mode, without a joystick yet. */
  public ArJoyHandler(boolean useOSCal) {
    this.useOSCal = useOSCal;
  }

  /**
   * Declares a joystick with {@code numAxes} axes and {@code numButtons} buttons (at most 8 and
   * 16); all values start centred and released.
   */
  public synchronized void connect(int numAxes, int numButtons) {
    if (numAxes < 2 || numAxes > MAX_AXES || numButtons < 0 || numButtons > MAX_BUTTONS) {
      throw new IllegalArgumentException(
          "a joystick has 2.."
              + MAX_AXES
              + " axes and 0.."
              + MAX_BUTTONS
              + " buttons, got "
              + numAxes
              + " and "
              + numButtons);
    }
    this.numAxes = numAxes;
    this.numButtons = numButtons;
    Arrays.fill(axes, 0);
    Arrays.fill(buttons, false);
    haveJoystick = true;
  }

  /** Declares the joystick gone. */
  public synchronized void disconnect() {
    haveJoystick = false;
    numAxes = 0;
    numButtons = 0;
  }

  /** ARIA's initialisation: returns whether a joystick is there. */
  public boolean init() {
    return haveJoystick();
  }

  /** Whether a joystick is connected. */
  public synchronized boolean haveJoystick() {
    return haveJoystick;
  }

  /** Whether the joystick has a third axis (a throttle). */
  public synchronized boolean haveZAxis() {
    return haveJoystick && numAxes >= 3;
  }

  /** Number of axes (numbered 1..n). */
  public synchronized int getNumAxes() {
    return numAxes;
  }

  /** Number of buttons (numbered 1..n). */
  public synchronized int getNumButtons() {
    return numButtons;
  }

  /**
   * Sets raw axis {@code axis} (1-based) to {@code value}, clamped to −128..128. Without OS
   * calibration the value also widens the tracked range.
   */
  public synchronized void setAxis(int axis, int value) {
    if (!haveJoystick || axis < 1 || axis > numAxes) {
      throw new IllegalArgumentException(
          "axis " + axis + " does not exist; the joystick has " + numAxes + " (connect it first)");
    }
    int v = Math.max(-128, Math.min(128, value));
    axes[axis] = v;
    if (!useOSCal) {
      if (axis == 1) {
        maxX = Math.max(maxX, v);
        minX = Math.min(minX, v);
      } else if (axis == 2) {
        maxY = Math.max(maxY, v);
        minY = Math.min(minY, v);
      }
    }
  }

  /** Sets the x (right positive), y (forward positive) and, if present, z raw axes. */
  public synchronized void setAxes(int x, int y, int z) {
    setAxis(1, x);
    setAxis(2, y);
    if (numAxes >= 3) {
      setAxis(3, z);
    }
  }

  /** Presses or releases button {@code button} (1-based). */
  public synchronized void setButton(int button, boolean pressed) {
    if (!haveJoystick || button < 1 || button > numButtons) {
      throw new IllegalArgumentException(
          "button "
              + button
              + " does not exist; the joystick has "
              + numButtons
              + " (connect it first)");
    }
    buttons[button] = pressed;
  }

  /** Whether button {@code button} (1-based) is pressed; false if there is no such button. */
  public synchronized boolean getButton(int button) {
    return haveJoystick && button >= 1 && button <= numButtons && buttons[button];
  }

  /** Axis {@code axis} (1-based) as −1..1 (raw / 128); 0 if there is no such axis. */
  public synchronized double getAxis(int axis) {
    if (!haveJoystick || axis < 1 || axis > numAxes) {
      return 0;
    }
    return axes[axis] / 128.0;
  }

  /** The raw x, y, z values, −128..128. */
  public synchronized JoyVec3i getUnfiltered() {
    return new JoyVec3i(axes[1], axes[2], numAxes >= 3 ? axes[3] : 0);
  }

  /** Sets the values {@link #getAdjusted()} reaches at full deflection. */
  public synchronized void setSpeeds(int x, int y, int z) {
    topX = x;
    topY = y;
    topZ = z;
  }

  /** The values set with {@link #setSpeeds}. */
  public synchronized JoyVec3i getSpeeds() {
    return new JoyVec3i(topX, topY, topZ);
  }

  /** Whether the values are trusted as calibrated (true) or calibrated here. */
  public synchronized boolean getUseOSCal() {
    return useOSCal;
  }

  /** Sets whether the values are trusted as calibrated (true) or calibrated here. */
  public synchronized void setUseOSCal(boolean useOSCal) {
    this.useOSCal = useOSCal;
  }

  /** Starts calibrating: the current position becomes centre, minimum and maximum. */
  public synchronized void startCal() {
    maxX = minX = cenX = axes[1];
    maxY = minY = cenY = axes[2];
  }

  /** Ends calibrating: the current position becomes the centre. */
  public synchronized void endCal() {
    cenX = axes[1];
    cenY = axes[2];
  }

  /** The calibration: maximum, minimum and centre of x and y. */
  public synchronized int[] getStats() {
    return new int[] {maxX, minX, maxY, minY, cenX, cenY};
  }

  /** Sets the calibration. */
  public synchronized void setStats(int maxX, int minX, int maxY, int minY, int cenX, int cenY) {
    this.maxX = maxX;
    this.minX = minX;
    this.maxY = maxY;
    this.minY = minY;
    this.cenX = cenX;
    this.cenY = cenY;
  }

  /**
   * The position as −1..1 on each axis (z as −1..1 too). With OS calibration it is raw / 128;
   * otherwise the fraction of the way from the centre to the maximum (or minimum), negative towards
   * the minimum.
   *
   * <p>ARIA's own calibration truncated these fractions to integers and lost their sign; here they
   * are what the documentation promises.
   */
  public synchronized JoyVec3f getDoubles() {
    double z = numAxes >= 3 ? axes[3] / 128.0 : 0;
    if (useOSCal) {
      return new JoyVec3f(axes[1] / 128.0, axes[2] / 128.0, z);
    }
    return new JoyVec3f(
        calibrated(axes[1], cenX, minX, maxX), calibrated(axes[2], cenY, minY, maxY), z);
  }

  /** The position scaled to the values set with {@link #setSpeeds}. */
  public synchronized JoyVec3i getAdjusted() {
    JoyVec3f d = getDoubles();
    return new JoyVec3i(
        (int) Math.round(d.x() * topX),
        (int) Math.round(d.y() * topY),
        (int) Math.round(d.z() * topZ));
  }

  private static double calibrated(int v, int cen, int min, int max) {
    if (v > cen && max - cen != 0) {
      return (double) (v - cen) / (max - cen);
    }
    if (v <= cen && cen - min != 0) {
      return -(double) (cen - v) / (cen - min);
    }
    return 0;
  }
}
