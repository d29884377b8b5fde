package org.jaria.net.data;

import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.NetEncodable;

/**
 * The localization's state in ARNL's {@code getLocState} layout, as ArNetworking's request
 * reference describes it: ubyte state; ubyte2 score 0..100. (JAria's fuller {@link
 * LocalizationSnapshot} is {@code getLocalizationSnapshot}.)
 *
 * @param state the state's number, in the order of ARNL's localization states ({@link #STATES})
 * @param score how well the sensors match the map, 0..100
 */
public record LocState(int state, int score) implements NetEncodable {

  /**
   * ARNL's localization states in their order: the number on the wire is the index. ARNL's source
   * is not public; the order is that of JAria's {@code LocalizationState}, which keeps ARNL's
   * names, and an ARNL server may number them differently.
   */
  public static final List<String> STATES =
      List.of(
          "NOT_INITIALIZED",
          "LOCALIZATION_FAILED",
          "LOCALIZATION_SUCCESS",
          "LOCALIZATION_INIT_COMPUTING",
          "LOCALIZATION_IDLE");

  /** Checks the ranges of the wire's fields. */
  public LocState {
    if (state < 0 || state > 255 || score < 0 || score > 100) {
      throw new IllegalArgumentException(
          "a localization state is 0..255 with a score 0..100, not " + state + ", " + score);
    }
  }

  /** ARNL's layout of JAria's snapshot: the state by name (unknown: 0), the score 0..1 × 100. */
  public static LocState of(LocalizationSnapshot s) {
    int state = Math.max(0, STATES.indexOf(s.state()));
    double score = Double.isFinite(s.score()) ? s.score() : 0;
    return new LocState(state, (int) Math.round(Math.min(1, Math.max(0, score)) * 100));
  }

  /** The state's name ("STATE_7" for a number JAria does not know). */
  public String stateName() {
    return state < STATES.size() ? STATES.get(state) : "STATE_" + state;
  }

  @Override
  public void write(ArNetPacket out) {
    out.uByteToBuf(state).uByte2ToBuf(score);
  }

  /**
   * Reads the layout.
   *
   * @throws ArNetPacketException if it is cut short or the score is over 100
   */
  public static LocState read(ArNetPacket in) {
    int state = in.bufToUByte();
    int score = in.bufToUByte2();
    if (score > 100) {
      throw new ArNetPacketException("a localization score is 0..100, not " + score);
    }
    return new LocState(state, score);
  }
}
