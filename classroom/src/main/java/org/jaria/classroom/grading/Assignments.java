package org.jaria.classroom.grading;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.jaria.classroom.ball.BallAssignment;
import org.jaria.classroom.goals.GoalsAssignment;
import org.jaria.classroom.square.SquareAssignment;
import org.jaria.classroom.wall.WallAssignment;

/** The kit's assignments, by id. */
public final class Assignments {

  private Assignments() {}

  /** Every assignment, in teaching order. */
  public static List<Assignment> all() {
    return List.of(
        new SquareAssignment(), new WallAssignment(), new GoalsAssignment(), new BallAssignment());
  }

  /**
   * The assignment called {@code id}.
   *
   * @throws IllegalArgumentException naming the ids there are, if there is none by that id
   */
  public static Assignment byId(String id) {
    Map<String, Assignment> byId = new LinkedHashMap<>();
    for (Assignment a : all()) {
      byId.put(a.id(), a);
    }
    Assignment a = byId.get(id);
    if (a == null) {
      throw new IllegalArgumentException(
          "no assignment called '" + id + "'; the assignments are: " + byId.keySet());
    }
    return a;
  }
}
