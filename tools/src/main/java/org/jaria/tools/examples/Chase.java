package org.jaria.tools.examples;

import java.util.concurrent.TimeUnit;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.acts.ArACTSBlob;
import org.jaria.acts.ArACTS_1_2;
import org.jaria.ptz.ArPTZ;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The thesis's Chase action (§6.4, {@code actsColorFollowingExample.cpp}): drives at 200 mm/s
 * towards the largest blob of one ACTS channel, turning by up to 10° a cycle and tilting the camera
 * to keep it in view. When no blob has been seen for a second it gives up (state {@link
 * State#NO_TARGET}) and wants nothing, so a lower-priority action (the program's "stop") takes
 * over.
 */
public final class Chase extends ArAction {

  private static final Logger log = LoggerFactory.getLogger(Chase.class);

  /** Whether a target is in view. */
  public enum State {
    /** No target in view. */
    NO_TARGET,
    /** A target in view. */
    TARGET
  }

  /** Image width from the frame grabber, pixels. */
  public static final int WIDTH = 160;

  /** Image height, pixels. */
  public static final int HEIGHT = 120;

  private final ArActionDesired desired = new ArActionDesired();
  private final ArACTS_1_2 acts;
  private final ArPTZ camera;
  private final ArACTSBlob blob = new ArACTSBlob();
  private final ArACTSBlob largestBlob = new ArACTSBlob();
  private volatile State state = State.NO_TARGET;
  private int channel;
  private long lastSeen = Long.MIN_VALUE / 2;
  private final long maxTime = TimeUnit.MILLISECONDS.toNanos(1000);

  /** Chases blobs that {@code acts} reports, tilting {@code camera}. */
  public Chase(ArACTS_1_2 acts, ArPTZ camera) {
    super("Chase", "Chases the largest blob.");
    this.acts = acts;
    this.camera = camera;
    setChannel(1);
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    long now = robot.getClock().nanoTime();
    boolean flag = false;
    int blobArea = 10;
    desired.reset();
    int numberOfBlobs = acts.getNumBlobs(channel);
    // If there are blobs, find the largest
    if (numberOfBlobs != 0) {
      for (int i = 0; i < numberOfBlobs; i++) {
        acts.getBlob(channel, i + 1, blob);
        if (blob.getArea() > blobArea) {
          flag = true;
          blobArea = blob.getArea();
          largestBlob.copyFrom(blob);
        }
      }
      lastSeen = now;
    }
    // No blob for a while: the target is lost
    if (now - lastSeen > maxTime) {
      if (state != State.NO_TARGET) {
        log.info("Target Lost");
      }
      state = State.NO_TARGET;
    } else {
      if (state != State.TARGET) {
        log.info("Target Acquired (using channel {} with {} blobs)", channel, numberOfBlobs);
      }
      state = State.TARGET;
    }
    if (state == State.TARGET && flag) {
      // Where is the blob's centre of gravity relative to the image centre?
      double xRel = (largestBlob.getXCG() - WIDTH / 2.0) / WIDTH;
      double yRel = (largestBlob.getYCG() - HEIGHT / 2.0) / HEIGHT;
      // Tilt the camera towards the blob
      if (!(Math.abs(yRel) < .20)) {
        if (-yRel > 0) {
          camera.tiltRel(1);
        } else {
          camera.tiltRel(-1);
        }
      }
      // Set the heading and velocity of the robot
      if (Math.abs(xRel) < .10) {
        desired.setDeltaHeading(0);
      } else {
        if (Math.abs(-xRel * 10) <= 10) {
          desired.setDeltaHeading(-xRel * 10);
        } else if (-xRel > 0) {
          desired.setDeltaHeading(10);
        } else {
          desired.setDeltaHeading(-10);
        }
      }
      desired.setVel(200);
      return desired;
    }
    // No target: want nothing, lower priorities decide
    return desired;
  }

  /** Chooses the ACTS channel, 1..32; false if out of range. */
  public boolean setChannel(int c) {
    if (c >= 1 && c <= ArACTS_1_2.NUM_CHANNELS) {
      channel = c;
      return true;
    }
    return false;
  }

  /** Whether a target is in view. */
  public State getState() {
    return state;
  }
}
