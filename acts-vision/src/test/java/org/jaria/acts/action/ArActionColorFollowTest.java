package org.jaria.acts.action;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.jaria.action.ArActionDesired;
import org.jaria.acts.ArACTS_1_2;
import org.jaria.acts.action.ArActionColorFollow.MoveState;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.image.ImageSource;
import org.jaria.acts.image.RgbImage;
import org.jaria.acts.server.ActsLink;
import org.jaria.acts.server.VisionPipeline;
import org.jaria.acts.testing.Pictures;
import org.jaria.connection.PipeConnection;
import org.jaria.ptz.ArVCC4;
import org.jaria.testing.LockstepRig;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * ArActionColorFollow with a real ACTS link (pipeline, protocol, client) on a lockstep robot: a red
 * square the test moves around a 160×120 picture stands for the target.
 */
class ArActionColorFollowTest {

  /** A picture with one red square wherever the test puts it (or none). */
  private static final class Square implements ImageSource {
    int x = -1;
    int y = -1;

    @Override
    public int width() {
      return 160;
    }

    @Override
    public int height() {
      return 120;
    }

    @Override
    public boolean nextFrame(int[] rgb) {
      Arrays.fill(rgb, RgbImage.pack(40, 40, 40));
      if (x >= 0) {
        for (int j = Math.max(0, y - 6); j < Math.min(120, y + 6); j++) {
          for (int i = Math.max(0, x - 6); i < Math.min(160, x + 6); i++) {
            rgb[j * 160 + i] = Pictures.RED;
          }
        }
      }
      return true;
    }
  }

  private final LockstepRig rig = new LockstepRig();
  private final Square picture = new Square();
  private final List<byte[]> cameraBytes = new ArrayList<>();
  private final ArVCC4 camera = new ArVCC4(cameraBytes::add);
  private ActsLink link;
  private ArActionColorFollow follow;

  @BeforeEach
  void setUp() throws IOException {
    PipeConnection.Pair pipe = PipeConnection.pair(rig.clock, "acts");
    pipe.b().open();
    link =
        new ActsLink(
            new VisionPipeline(picture, Pictures.rgbBank(), TrackerSettings.DEFAULT), pipe.b());
    ArACTS_1_2 acts = new ArACTS_1_2(rig.clock);
    acts.setReadTimeouts(0, 0); // lockstep: the reply is read on the next cycle
    assertTrue(rig.connect());
    assertTrue(acts.openPort(rig.robot, pipe.a()), acts.getOpenMessage());
    follow = new ArActionColorFollow("follow", acts, camera);
    rig.robot.addAction(follow, 50);
    follow.startMovement();
  }

  /** Runs {@code ms} of virtual time, serving ACTS requests between ticks. */
  private void run(long ms) {
    for (long t = 0; t < ms; t += LockstepRig.TICK_MS) {
      rig.tick();
      try {
        link.pump();
      } catch (IOException e) {
        throw new UncheckedIOException(e);
      }
    }
  }

  private ArActionDesired desire() {
    return rig.robot.getActionDesired();
  }

  @Test
  void aCentredTargetIsDrivenAtAriasSpeedWithoutTurning() {
    picture.x = 80;
    picture.y = 60;
    run(500);
    assertTrue(follow.getBlob());
    assertEquals(MoveState.FOLLOWING, follow.getMoveState());
    assertEquals(200, desire().getVel(), 1e-9);
    assertEquals(0, desire().getDeltaHeading(), 1e-9);
  }

  @Test
  void aTargetLeftOfCentreTurnsTheRobotLeftAndRightOfCentreRight() {
    picture.x = 40; // a quarter of the width left of centre
    picture.y = 60;
    run(500);
    assertEquals(2.5, desire().getDeltaHeading(), 0.3, "left: positive turn, 10 x 0.25");
    picture.x = 150;
    run(500);
    assertTrue(desire().getDeltaHeading() < -4, "far right: " + desire().getDeltaHeading());
  }

  @Test
  void aTargetHighInThePictureTiltsTheCameraUp() {
    picture.x = 80;
    picture.y = 10;
    run(500);
    assertTrue(camera.getTilt() > 0, "tilted up to " + camera.getTilt());
    assertFalse(cameraBytes.isEmpty(), "tilt commands went to the camera");
  }

  @Test
  void aLostTargetIsSearchedForAfterTwoSecondsOrStoppedWithoutAcquire() {
    picture.x = 80;
    picture.y = 60;
    run(500);
    picture.x = -1; // gone
    run(1500);
    assertTrue(follow.getBlob(), "within two seconds it still counts as seen");
    assertEquals(200, desire().getVel(), 1e-9, "heads on where it was last (centre)");
    run(1000);
    assertFalse(follow.getBlob());
    assertEquals(MoveState.ACQUIRING, follow.getMoveState());
    assertEquals(0, desire().getVel(), 1e-9);
    assertEquals(8, desire().getDeltaHeading(), 1e-9, "turns on the spot to search");
    follow.setAcquire(false);
    run(200);
    assertEquals(MoveState.STOPPED, follow.getMoveState());
    assertEquals(0, desire().getDeltaHeading(), 1e-9);
  }

  @Test
  void stopMovementKeepsTrackingButDoesNotDrive() {
    follow.stopMovement();
    picture.x = 40;
    picture.y = 60;
    run(500);
    assertTrue(follow.getBlob(), "still tracks");
    assertEquals(0, desire().getVel(), 1e-9);
    assertEquals(0, desire().getDeltaHeading(), 1e-9);
    assertFalse(follow.getMovement());
  }

  @Test
  void channelsOutsideOneToThirtyTwoAreRefused() {
    assertFalse(follow.setChannel(0));
    assertFalse(follow.setChannel(33));
    assertTrue(follow.setChannel(2));
    assertEquals(2, follow.getChannel());
    picture.x = 80; // red is not on channel 2 (green): no target there
    picture.y = 60;
    run(3000);
    assertFalse(follow.getBlob());
  }
}
