package org.jaria.acts.action;

import java.util.concurrent.TimeUnit;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.acts.ArACTSBlob;
import org.jaria.acts.ArACTS_1_2;
import org.jaria.ptz.ArPTZ;
import org.jaria.robot.ArRobot;

/**
 * Follows the largest blob of one ACTS channel (ARIA's {@code ArActionColorFollow}): turns towards
 * it (up to 10° per cycle), drives at the set speed, and tilts the camera to keep it in view. When
 * the blob has not been seen for two seconds the target counts as lost; then, if acquiring is on,
 * the robot turns on the spot to search, otherwise it stops. Like ARIA's, the action starts with
 * movement off: call {@link #startMovement()}.
 */
public class ArActionColorFollow extends ArAction {

  /** Whether a target is in view. */
  public enum TargetState {
    NO_TARGET,
    TARGET
  }

  /** What the action is doing. */
  public enum MoveState {
    FOLLOWING,
    ACQUIRING,
    STOPPED
  }

  /** Where the blob was last, relative to the image centre. */
  public enum LocationState {
    LEFT,
    CENTER,
    RIGHT
  }

  private final ArActionDesired desired = new ArActionDesired();
  private final ArACTSBlob blob = new ArACTSBlob();
  private final ArACTSBlob largest = new ArACTSBlob();
  private final ArACTS_1_2 acts;
  private volatile ArPTZ camera;
  private final double speed;
  private final int width;
  private final int height;
  private volatile int channel = 1;
  private volatile boolean acquire = true;
  private volatile boolean killMovement = true;
  private volatile TargetState state = TargetState.NO_TARGET;
  private volatile MoveState move = MoveState.STOPPED;
  // Only fire(), on the robot's cycle thread, uses these.
  private LocationState location = LocationState.CENTER;
  private long lastSeenNanos = Long.MIN_VALUE / 2;
  private final long maxTimeNanos = TimeUnit.MILLISECONDS.toNanos(2000);

  /** ARIA's defaults: speed 200 mm/s, a 160×120 image. */
  public ArActionColorFollow(String name, ArACTS_1_2 acts, ArPTZ camera) {
    this(name, acts, camera, 200, 160, 120);
  }

  /** A colour-following action; {@code camera} may be null (no tilting). */
  public ArActionColorFollow(
      String name, ArACTS_1_2 acts, ArPTZ camera, double speed, int width, int height) {
    super(name, "Follows the largest blob of color.");
    this.acts = acts;
    this.camera = camera;
    this.speed = speed;
    this.width = width;
    this.height = height;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    desired.reset();
    ArRobot robot = getRobot();
    long now = robot == null ? 0 : robot.getClock().nanoTime();
    boolean haveBlob = false;
    if (acts != null) {
      int n = acts.getNumBlobs(channel);
      int bestArea = 20;
      for (int i = 1; i <= n; i++) {
        if (acts.getBlob(channel, i, blob) && blob.getArea() > bestArea) {
          haveBlob = true;
          bestArea = blob.getArea();
          largest.copyFrom(blob);
        }
      }
      if (n != 0) {
        lastSeenNanos = now;
      }
      state = now - lastSeenNanos > maxTimeNanos ? TargetState.NO_TARGET : TargetState.TARGET;
      if (state == TargetState.TARGET) {
        move = MoveState.FOLLOWING;
      } else {
        move = acquire ? MoveState.ACQUIRING : MoveState.STOPPED;
      }
    } else {
      state = TargetState.NO_TARGET;
      move = MoveState.STOPPED;
    }

    if (move == MoveState.FOLLOWING) {
      if (haveBlob) {
        double xRel = (largest.getXCG() - width / 2.0) / width;
        double yRel = (largest.getYCG() - height / 2.0) / height;
        ArPTZ cam = camera;
        if (Math.abs(yRel) >= .20 && cam != null) {
          cam.tiltRel(-yRel > 0 ? 1 : -1);
        }
        if (!killMovement) {
          steer(xRel);
          desired.setVel(speed);
          return desired;
        }
      } else if (!killMovement) {
        // Not in this frame, but seen recently: head where it was last.
        switch (location) {
          case LEFT -> {
            desired.setDeltaHeading(-10);
            desired.setVel(0);
          }
          case RIGHT -> {
            desired.setDeltaHeading(10);
            desired.setVel(0);
          }
          case CENTER -> {
            desired.setDeltaHeading(0);
            desired.setVel(speed);
          }
        }
        return desired;
      }
    } else if (move == MoveState.ACQUIRING) {
      ArPTZ cam = camera;
      if (cam != null) {
        cam.tilt(0);
      }
      if (!killMovement) {
        desired.setVel(0);
        desired.setDeltaHeading(8);
        return desired;
      }
    }
    desired.setVel(0);
    desired.setDeltaHeading(0);
    return desired;
  }

  /**
   * Turns towards a blob {@code xRel} of the image width off centre (negative: left of centre, so
   * turn left). ARIA names the sides by where the robot must turn; kept for porting.
   */
  private void steer(double xRel) {
    if (Math.abs(xRel) < .10) {
      location = LocationState.CENTER;
      desired.setDeltaHeading(0);
    } else if (Math.abs(xRel * 10) <= 10) {
      location = xRel < 0 ? LocationState.RIGHT : LocationState.LEFT;
      desired.setDeltaHeading(-xRel * 10);
    } else if (xRel < 0) {
      location = LocationState.RIGHT;
      desired.setDeltaHeading(10);
    } else {
      location = LocationState.LEFT;
      desired.setDeltaHeading(-10);
    }
  }

  /** The ACTS channel to follow, 1..32; returns false if out of range. */
  public boolean setChannel(int c) {
    if (c < 1 || c > ArACTS_1_2.NUM_CHANNELS) {
      return false;
    }
    channel = c;
    return true;
  }

  /** The channel followed. */
  public int getChannel() {
    return channel;
  }

  /** Sets the camera to tilt (null: none). */
  public void setCamera(ArPTZ cam) {
    camera = cam;
  }

  /** Whether to turn and search when no target is in view. */
  public void setAcquire(boolean on) {
    acquire = on;
  }

  /** Whether searching is on. */
  public boolean getAcquire() {
    return acquire;
  }

  /** Stops the robot from moving (the action still tracks and tilts the camera). */
  public void stopMovement() {
    killMovement = true;
  }

  /** Lets the action move the robot. */
  public void startMovement() {
    killMovement = false;
  }

  /** Whether the action may move the robot. */
  public boolean getMovement() {
    return !killMovement;
  }

  /** Whether a target is in view (seen within the last two seconds). */
  public boolean getBlob() {
    return state == TargetState.TARGET;
  }

  /** What the action is doing now. */
  public MoveState getMoveState() {
    return move;
  }
}
