package org.jaria.classroom.grading;

import java.lang.reflect.Modifier;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/** Finds, among a student's compiled classes, the one that is the solution. */
public final class SolutionFinder {

  private SolutionFinder() {}

  /** A class loader for the classes compiled into {@code classesDir}, on top of JAria's. */
  public static URLClassLoader loaderFor(Path classesDir) {
    return loaderFor(classesDir, SolutionFinder.class.getClassLoader());
  }

  /**
   * A class loader for the classes compiled into {@code classesDir}, on top of {@code parent} (the
   * loader of a pack's assignment, so a solution may use the pack's own types).
   */
  public static URLClassLoader loaderFor(Path classesDir, ClassLoader parent) {
    try {
      return new URLClassLoader("submission", new URL[] {classesDir.toUri().toURL()}, parent);
    } catch (MalformedURLException e) {
      throw new IllegalArgumentException("not a folder: " + classesDir, e);
    }
  }

  /**
   * The solution class among {@code classNames}: one of the assignment's type, preferring the
   * starter's class name.
   *
   * @throws Solutions.SolutionException naming what was found and what is needed
   */
  public static Class<?> find(Assignment a, ClassLoader loader, List<String> classNames)
      throws Solutions.SolutionException {
    List<Class<?>> fits = new ArrayList<>();
    List<String> seen = new ArrayList<>();
    for (String name : classNames) {
      if (name.contains("$") || name.endsWith("package-info") || name.endsWith("module-info")) {
        continue;
      }
      Class<?> c;
      try {
        c = Class.forName(name, false, loader);
      } catch (ClassNotFoundException | LinkageError e) {
        continue;
      }
      seen.add(c.getSimpleName());
      if (a.solutionType().isAssignableFrom(c)
          && !c.isInterface()
          && !Modifier.isAbstract(c.getModifiers())) {
        fits.add(c);
      }
    }
    for (Class<?> c : fits) {
      if (c.getSimpleName().equals(a.solutionClassName())) {
        return c;
      }
    }
    if (!fits.isEmpty()) {
      return fits.get(0);
    }
    String own = "setup.noSolution." + a.id();
    if (Texts.english().has(own)) {
      throw new Solutions.SolutionException(null, own, seen.toString());
    }
    throw new Solutions.SolutionException(
        null, "setup.noSolution", seen.toString(), a.solutionShape());
  }
}
