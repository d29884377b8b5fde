package org.jaria.apps.mapper;

import java.util.Locale;

/** The map object types the editor draws with their own tools and symbols. */
public enum ObjectKind {
  /** A goal the robot can be sent to. */
  GOAL("Goal", "goal", true, false),
  /** A goal to be reached facing a given direction. */
  GOAL_WITH_HEADING("GoalWithHeading", "goal with heading", true, true),
  /** Where the robot starts (localization's initial pose). */
  HOME("RobotHome", "home", false, true),
  /** A docking (charging) station. */
  DOCK("Dock", "dock", false, true),
  /** A line the robot must not cross. */
  FORBIDDEN_LINE("ForbiddenLine", "forbidden line", false, false),
  /** An area the robot must not enter. */
  FORBIDDEN_AREA("ForbiddenArea", "forbidden area", false, false);

  private final String type;
  private final String label;
  private final boolean goal;
  private final boolean heading;

  ObjectKind(String type, String label, boolean goal, boolean heading) {
    this.type = type;
    this.label = label;
    this.goal = goal;
    this.heading = heading;
  }

  /** The type word in map files ("ForbiddenArea"). */
  public String type() {
    return type;
  }

  /** A lower-case name for people ("forbidden area"). */
  public String label() {
    return label;
  }

  /** Whether the robot can be sent to it. */
  public boolean isGoal() {
    return goal;
  }

  /** Whether its heading matters (drawn as an arrow). */
  public boolean hasHeading() {
    return heading;
  }

  /** The kind of a type word, ignoring case, or null for other (custom) types. */
  public static ObjectKind of(String type) {
    for (ObjectKind k : values()) {
      if (k.type.equalsIgnoreCase(type)) {
        return k;
      }
    }
    return null;
  }

  /** A name for people for any type word: the kind's label, or the type itself. */
  public static String describe(String type) {
    ObjectKind k = of(type);
    return k != null ? k.label : type.toLowerCase(Locale.ROOT);
  }
}
