package org.jaria.net.data;

import org.jaria.geom.ArPose;
import org.jaria.net.ArNetPacket;
import org.jaria.net.NetEncodable;

/**
 * Where the localization thinks the robot is and how sure it is ({@code "getLocState"}).
 *
 * @param state the localizer's state, e.g. "LOCALIZED", "LOST", "INITIALIZING"
 * @param score how well the sensors match the map, 0..1
 * @param pose the estimated pose (null if unknown)
 * @param numSamples particles in use
 * @param lost whether the localizer considers the robot lost
 */
public record LocalizationSnapshot(
    String state, double score, ArPose pose, int numSamples, boolean lost) implements NetEncodable {

  private static final int FIELDS = 5;

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(FIELDS).strToBuf(state).doubleToBuf(score);
    Fields.writePose(out, pose);
    out.intToBuf(numSamples).boolToBuf(lost);
  }

  /** Reads what {@link #write} wrote. */
  public static LocalizationSnapshot read(ArNetPacket in) {
    int n = Fields.begin(in, FIELDS, "a localization state");
    LocalizationSnapshot s =
        new LocalizationSnapshot(
            in.bufToStr(), in.bufToDouble(), Fields.readPose(in), in.bufToInt(), in.bufToBool());
    Fields.end(in, n, FIELDS);
    return s;
  }
}
