package org.jaria.net.data;

import org.jaria.net.ArNetPacket;
import org.jaria.net.NetEncodable;

/**
 * The localizer's particles ({@code "getLocPoints"}).
 *
 * @param updateCount the localizer's update counter: particles with the same count are the same
 * @param samples the particles' poses (with headings)
 */
public record Particles(long updateCount, Points samples) implements NetEncodable {

  /** No particles. */
  public static final Particles NONE = new Particles(0, Points.EMPTY);

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(2).intToBuf(updateCount);
    samples.write(out);
  }

  /** Reads what {@link #write} wrote. */
  public static Particles read(ArNetPacket in) {
    int n = Fields.begin(in, 2, "particles");
    Particles p = new Particles(in.bufToLong(), Points.read(in));
    Fields.end(in, n, 2);
    return p;
  }
}
