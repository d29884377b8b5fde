package org.jaria.ptz;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.robot.ArRobot;

/**
 * A Directed Perception pan-tilt unit (ARIA's {@code ArDPPTU}), the PTU-46-17.5 by default: one
 * position step is 0.0514° on both axes (0.0129° of tilt on the PTU-46-70), pan ±159°, tilt
 * −47°..+31° (used as ±31° here). Commands are ASCII: PP/TP absolute position, PS/TS speed, I
 * immediate mode, R reset, H halt.
 *
 * <p>Through the robot, the unit's answers are fetched: {@code *} lines are counted as done, {@code
 * !} lines as errors, and {@link #requestPosition()} sends the PP and TP queries whose answers
 * ({@code "* Current Pan position is 195"}) fill {@link #getReportedPan()} and {@link
 * #getReportedTilt()}.
 */
public class ArDPPTU extends ArPTZ {

  /** The models JAria knows, with their step sizes. */
  public enum Model {
    /** PTU-46-17.5: 0.0514° per step on both axes. */
    PANTILT_PTU46(0.0514, 0.0514),
    /** PTU-46-70: 0.0514° per pan step, 0.0129° per tilt step. */
    PANTILT_PTU46_70(0.0514, 0.0129);

    final double panDegPerStep;
    final double tiltDegPerStep;

    Model(double pan, double tilt) {
      this.panDegPerStep = pan;
      this.tiltDegPerStep = tilt;
    }
  }

  /** Largest pan, degrees. */
  public static final double MAX_PAN = 158;

  /** Largest tilt, degrees. */
  public static final double MAX_TILT = 30;

  /** Bytes of the shortest answer, {@code "*\r\n"}. */
  static final int DONE_BYTES = 3;

  private static final String PAN_ANSWER = "* Current Pan position is ";
  private static final String TILT_ANSWER = "* Current Tilt position is ";

  private final Model model;
  private final Object parseLock = new Object();

  @GuardedBy("parseLock")
  private final StringBuilder line = new StringBuilder();

  private final AtomicLong done = new AtomicLong();
  private final AtomicLong errors = new AtomicLong();
  private volatile String lastError;

  /** A PTU-46-17.5 on {@code robot}'s AUX1 port. */
  public ArDPPTU(ArRobot robot) {
    this(robot, Model.PANTILT_PTU46);
  }

  /** A unit of {@code model} on {@code robot}'s AUX1 port. */
  public ArDPPTU(ArRobot robot, Model model) {
    super(robot);
    this.model = model;
  }

  @Override
  public boolean init() {
    return command(DpptuText.command("I")) && panTilt(0, 0);
  }

  @Override
  public String getTypeName() {
    return "dpptu";
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
  protected boolean panTiltClamped(double panDeg, double tiltDeg) {
    return command(DpptuText.command("PP", (int) Math.round(panDeg / model.panDegPerStep)))
        && command(DpptuText.command("TP", (int) Math.round(tiltDeg / model.tiltDegPerStep)));
  }

  @Override
  public boolean canPanTiltSlew() {
    return true;
  }

  /** Sets the pan speed, degrees per second. */
  @Override
  public boolean panSlew(double degPerSec) {
    return command(DpptuText.command("PS", (int) Math.round(degPerSec / model.panDegPerStep)));
  }

  /** Sets the tilt speed, degrees per second. */
  @Override
  public boolean tiltSlew(double degPerSec) {
    return command(DpptuText.command("TS", (int) Math.round(degPerSec / model.tiltDegPerStep)));
  }

  /** Recalibrates both axes (the unit sweeps to its limits). */
  public boolean resetCalib() {
    return command(DpptuText.command("R"));
  }

  /** Stops both axes. */
  public boolean haltAll() {
    return command(DpptuText.command("H"));
  }

  /** Sends the PP and TP queries; the answers arrive in {@link #getReportedPan()} and tilt. */
  @Override
  public boolean requestPosition() {
    if (!send(DpptuText.command("PP"))) {
      return false;
    }
    expectReply(PAN_ANSWER.length() + DONE_BYTES);
    if (!send(DpptuText.command("TP"))) {
      return false;
    }
    expectReply(TILT_ANSWER.length() + DONE_BYTES);
    return true;
  }

  private boolean command(byte[] bytes) {
    if (!send(bytes)) {
      return false;
    }
    expectReply(DONE_BYTES);
    return true;
  }

  @Override
  protected void replyBytes(byte[] data) {
    boolean midLine;
    for (byte b : data) {
      String whole = null;
      synchronized (parseLock) {
        char c = (char) (b & 0xFF);
        if (c == '\n') {
          whole = line.toString().strip();
          line.setLength(0);
        } else if (line.length() < 128) {
          line.append(c);
        }
      }
      if (whole != null && !whole.isEmpty()) {
        take(whole);
      }
    }
    synchronized (parseLock) {
      midLine = line.length() > 0;
    }
    // an answer longer than expected (more digits, an error text): fetch the rest of its line
    if (midLine && getRepliesOutstanding() == 0) {
      expectReply(1);
    }
  }

  private void take(String answer) {
    try {
      if (answer.startsWith("!")) {
        errors.incrementAndGet();
        lastError = answer;
      } else if (answer.startsWith(PAN_ANSWER)) {
        double steps = Double.parseDouble(answer.substring(PAN_ANSWER.length()).strip());
        setReportedPanTilt(steps * model.panDegPerStep, getReportedTiltOrZero());
      } else if (answer.startsWith(TILT_ANSWER)) {
        double steps = Double.parseDouble(answer.substring(TILT_ANSWER.length()).strip());
        setReportedPanTilt(getReportedPanOrZero(), steps * model.tiltDegPerStep);
      } else if (answer.startsWith("*")) {
        done.incrementAndGet();
      }
    } catch (NumberFormatException e) {
      // a garbled position answer: counted, and the last good position stays
      errors.incrementAndGet();
      lastError = answer;
    }
  }

  private double getReportedPanOrZero() {
    double p = getReportedPan();
    return Double.isNaN(p) ? 0 : p;
  }

  private double getReportedTiltOrZero() {
    double t = getReportedTilt();
    return Double.isNaN(t) ? 0 : t;
  }

  /** Commands the unit answered as done ({@code *}). */
  public long getDoneCount() {
    return done.get();
  }

  /** Error answers ({@code !}) received. */
  public long getErrorCount() {
    return errors.get();
  }

  /** The last error answer, or null. */
  public String getLastError() {
    return lastError;
  }
}
