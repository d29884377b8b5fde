import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.acts.ArACTSBlob;
import org.jaria.acts.ArACTS_1_2;

/**
 * Assignment 4 (reference solution): the thesis's Chase action without the camera tilt: drive at up
 * to 200 mm/s towards the largest blob of channel 1, turning in proportion to how far it is from
 * the middle of the image, slowing down as the ball gets near (low in the image), and want nothing
 * once no blob has been seen for a second.
 */
public class BallFollower extends ArAction {

  private static final int CHANNEL = 1;
  private static final int WIDTH = 160;
  private static final int BOTTOM = 106; // stop when the blob's centre is this low
  private static final long LOST_AFTER_NANOS = 1_000_000_000L;

  private final ArACTS_1_2 acts;
  private final ArActionDesired desired = new ArActionDesired();
  private final ArACTSBlob blob = new ArACTSBlob();
  private final ArACTSBlob largest = new ArACTSBlob();
  private long lastSeen = Long.MIN_VALUE / 2;

  public BallFollower(ArACTS_1_2 acts) {
    super("ball follower", "drives towards the largest blob of ACTS channel 1");
    this.acts = acts;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    long now = getRobot().getClock().nanoTime();
    int largestArea = 10; // ignore specks
    boolean found = false;
    for (int i = 1; i <= acts.getNumBlobs(CHANNEL); i++) {
      if (acts.getBlob(CHANNEL, i, blob) && blob.getArea() > largestArea) {
        largestArea = blob.getArea();
        largest.copyFrom(blob);
        found = true;
      }
    }
    if (found) {
      lastSeen = now;
    }
    if (now - lastSeen > LOST_AFTER_NANOS) {
      return null; // lost: let the lower-priority stop action have the robot
    }
    desired.reset();
    double speed = 200;
    if (found) {
      double xRel = (largest.getXCG() - WIDTH / 2.0) / WIDTH; // -0.5 (left) .. 0.5 (right)
      desired.setDeltaHeading(Math.abs(xRel) < 0.05 ? 0 : Math.max(-10, Math.min(10, -xRel * 25)));
      // The camera looks slightly down: a near ball sits low in the image and drops out of view
      // when the robot gets too close, so slow down as the blob nears the bottom.
      speed = 200 * Math.max(0, Math.min(1, (BOTTOM - largest.getYCG()) / 15.0));
    }
    desired.setVel(speed);
    return desired;
  }
}
