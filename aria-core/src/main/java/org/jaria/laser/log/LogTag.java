package org.jaria.laser.log;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.jaria.geom.ArPose;

/**
 * A tag logged at a moment of the drive, with the robot's pose then: most often a goal placed while
 * driving ({@code cairn: GoalWithHeading "" ICON_GOALWITHHEADING "goal1"}), which a map builder
 * turns into a goal of the map; also {@code loop: start 1} and tags a program adds with {@code
 * addTagToLog}.
 *
 * @param time seconds since logging started
 * @param robotPose the robot's odometry pose at the tag
 * @param globalPose its localized pose, or null if not logged
 * @param text the tag's line as logged, e.g. {@code cairn: GoalWithHeading "" ICON "goal1"}
 */
public record LogTag(double time, ArPose robotPose, ArPose globalPose, String text)
    implements ScanLogEntry {

  /** Checks the values. */
  public LogTag {
    Objects.requireNonNull(robotPose, "robotPose");
    Objects.requireNonNull(text, "text");
    if (text.indexOf('\n') >= 0 || text.indexOf('\r') >= 0) {
      throw new IllegalArgumentException("a log tag is one line: " + text.strip());
    }
  }

  /** The localized pose, if logged. */
  public Optional<ArPose> global() {
    return Optional.ofNullable(globalPose);
  }

  /** Whether this tag places a map object ({@code cairn: TYPE "" ICON "NAME"}). */
  public boolean isCairn() {
    return text.startsWith("cairn:") && words().size() >= 2;
  }

  /** The map object's type ({@code GoalWithHeading}), empty if this is no cairn. */
  public String cairnType() {
    List<String> w = words();
    return isCairn() ? w.get(1) : "";
  }

  /** The map object's name (the last quoted word, e.g. {@code goal1}), empty if none. */
  public String cairnName() {
    List<String> w = words();
    return isCairn() && w.size() >= 5 ? w.get(4) : "";
  }

  /** The text's words, with double quotes grouping (and removed). */
  private List<String> words() {
    List<String> out = new ArrayList<>();
    StringBuilder cur = new StringBuilder();
    boolean quoted = false;
    boolean any = false;
    for (int i = 0; i < text.length(); i++) {
      char c = text.charAt(i);
      if (c == '"') {
        quoted = !quoted;
        any = true;
      } else if (c == ' ' && !quoted) {
        if (any) {
          out.add(cur.toString());
        }
        cur.setLength(0);
        any = false;
      } else {
        cur.append(c);
        any = true;
      }
    }
    if (any) {
      out.add(cur.toString());
    }
    return out;
  }
}
