import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.acts.ArACTSBlob;
import org.jaria.acts.ArACTS_1_2;

/**
 * Assignment 4 (starter): an action that drives towards the largest blob ACTS sees on channel 1
 * (trained on a red ball), and gives up when it has seen none for a second. The camera's image is
 * 160 x 120 pixels.
 *
 * <p>Grade it: {@code ./jaria grade --assignment ball FOLDER} (FOLDER holds this file).
 */
public class BallFollower extends ArAction {

  private static final int CHANNEL = 1;

  private final ArACTS_1_2 acts;
  private final ArActionDesired desired = new ArActionDesired();
  private final ArACTSBlob blob = new ArACTSBlob();

  public BallFollower(ArACTS_1_2 acts) {
    super("ball follower", "drives towards the largest blob of ACTS channel 1");
    this.acts = acts;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    desired.reset();
    int blobs = acts.getNumBlobs(CHANNEL);
    for (int i = 1; i <= blobs; i++) {
      acts.getBlob(CHANNEL, i, blob); // blob numbers start at 1
      // TODO remember the largest blob (blob.getArea())
    }
    // TODO if there is a blob: drive forward (desired.setVel) and turn towards it
    //      (desired.setDeltaHeading, positive = left; blob.getXCG() < 80 means it is left)
    // TODO if no blob has been seen for a second (getRobot().getClock().nanoTime()), return null
    return null;
  }
}
