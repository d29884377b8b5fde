package org.jaria.classroom.grading;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;

/**
 * The assignments there are, by id: every {@link Assignment} the packs on a class path list (see
 * {@link Assignment}). The kit's own four (square, wall, goals, ball) are a pack like any other, in
 * the classroom jar; {@code jaria grade --pack} adds a teacher's.
 */
public final class Assignments {

  private Assignments() {}

  /** Every assignment of the kit's own pack, in teaching order. */
  public static List<Assignment> all() {
    return all(Assignments.class.getClassLoader());
  }

  /**
   * Every assignment the packs visible to {@code loader} list, the kit's first.
   *
   * @throws IllegalStateException if a pack cannot be loaded or two assignments share an id
   */
  public static List<Assignment> all(ClassLoader loader) {
    Map<String, Assignment> byId = new LinkedHashMap<>();
    try {
      for (Assignment a : ServiceLoader.load(Assignment.class, loader)) {
        Assignment before = byId.putIfAbsent(a.id(), a);
        if (before != null && before.getClass() != a.getClass()) {
          throw new IllegalStateException(
              "two assignments are called '"
                  + a.id()
                  + "': "
                  + before.getClass().getName()
                  + " and "
                  + a.getClass().getName()
                  + "; give one another id()");
        }
      }
    } catch (ServiceConfigurationError e) {
      throw new IllegalStateException("an assignment pack cannot be loaded: " + e.getMessage(), e);
    }
    return new ArrayList<>(byId.values());
  }

  /**
   * The kit's assignment called {@code id}.
   *
   * @throws IllegalArgumentException naming the ids there are, if there is none by that id
   */
  public static Assignment byId(String id) {
    return byId(id, all());
  }

  /**
   * The assignment called {@code id} among {@code from}.
   *
   * @throws IllegalArgumentException naming the ids there are, if there is none by that id
   */
  public static Assignment byId(String id, List<Assignment> from) {
    List<String> ids = new ArrayList<>();
    for (Assignment a : from) {
      if (a.id().equals(id)) {
        return a;
      }
      ids.add(a.id());
    }
    throw new IllegalArgumentException(
        "no assignment called '" + id + "'; the assignments are: " + ids);
  }
}
