package org.jaria.classroom.grading;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Modifier;
import java.util.Arrays;
import java.util.stream.Collectors;

/** Making an object of a student's class, with messages that say what is wrong with it. */
public final class Solutions {

  private Solutions() {}

  /** Thrown when a solution class cannot be made into an object; the message is for the student. */
  public static final class SolutionException extends Exception {
    private static final long serialVersionUID = 1L;

    /** A problem described for the student. */
    public SolutionException(String message, Throwable cause) {
      super(message, cause);
    }
  }

  /**
   * A new {@code type} object from {@code solution}'s public constructor taking {@code argTypes}.
   *
   * @throws SolutionException if the class is not of the right type, has no such public
   *     constructor, or its constructor throws
   */
  public static <T> T instantiate(
      Class<?> solution, Class<T> type, Class<?>[] argTypes, Object... args)
      throws SolutionException {
    String name = solution.getSimpleName();
    if (!type.isAssignableFrom(solution)) {
      throw new SolutionException(
          name + " must " + (type.isInterface() ? "implement " : "extend ") + type.getName(), null);
    }
    if (Modifier.isAbstract(solution.getModifiers())) {
      throw new SolutionException(name + " must not be abstract", null);
    }
    if (!Modifier.isPublic(solution.getModifiers())) {
      throw new SolutionException("declare it 'public class " + name + "'", null);
    }
    Constructor<?> c;
    try {
      c = solution.getConstructor(argTypes);
    } catch (NoSuchMethodException e) {
      String wanted =
          argTypes.length == 0
              ? "a public constructor with no arguments"
              : "a public constructor " + name + "(" + simpleNames(argTypes) + ")";
      throw new SolutionException(name + " needs " + wanted, e);
    }
    try {
      return type.cast(c.newInstance(args));
    } catch (InvocationTargetException e) {
      Throwable t = e.getCause();
      throw new SolutionException(
          "the constructor of " + name + " threw " + describe(t), t == null ? e : t);
    } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
      throw new SolutionException("cannot create a " + name + ": " + e, e);
    }
  }

  private static String simpleNames(Class<?>[] types) {
    return Arrays.stream(types).map(Class::getSimpleName).collect(Collectors.joining(", "));
  }

  /**
   * An exception as a student wants to read it: its type, its message and the line of their own
   * code where it happened (the first stack frame outside JAria and the JDK).
   */
  public static String describe(Throwable t) {
    if (t == null) {
      return "an unknown error";
    }
    StringBuilder sb = new StringBuilder(t.getClass().getSimpleName());
    if (t.getMessage() != null) {
      sb.append(" (").append(t.getMessage()).append(')');
    }
    for (StackTraceElement e : t.getStackTrace()) {
      String cls = e.getClassName();
      if (cls.startsWith("java.")
          || cls.startsWith("jdk.")
          || cls.startsWith("sun.")
          || cls.startsWith("org.jaria.")) {
        continue;
      }
      sb.append(" at ").append(e.getFileName()).append(':').append(e.getLineNumber());
      sb.append(" (in ").append(e.getMethodName()).append(')');
      break;
    }
    return sb.toString();
  }
}
