package org.jaria.classroom.grading;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Collectors;

/** Making an object of a student's class, with messages that say what is wrong with it. */
public final class Solutions {

  private Solutions() {}

  /**
   * Thrown when a solution class cannot be made into an object. What it says for the student is a
   * sentence of the checks' catalogue ({@link Texts}), its key and the words that fill its holes,
   * so the grader can say it in the student's language; the message is the English sentence.
   */
  public static final class SolutionException extends Exception {
    private static final long serialVersionUID = 1L;

    /** The catalogue key. */
    private final String key;

    /** What fills the sentence's holes. */
    @SuppressWarnings("serial") // a List.of of strings
    private final List<String> args;

    /** The problem of catalogue sentence {@code key}, its holes filled with {@code args}. */
    public SolutionException(Throwable cause, String key, String... args) {
      super(Texts.english().get(key, (Object[]) args), cause);
      this.key = key;
      this.args = List.of(args);
    }

    /** The catalogue key. */
    public String key() {
      return key;
    }

    /** What fills the sentence's holes. */
    public List<String> args() {
      return args;
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
          null,
          type.isInterface() ? "setup.mustImplement" : "setup.mustExtend",
          name,
          type.getName());
    }
    if (Modifier.isAbstract(solution.getModifiers())) {
      throw new SolutionException(null, "setup.abstract", name);
    }
    if (!Modifier.isPublic(solution.getModifiers())) {
      throw new SolutionException(null, "setup.notPublic", name);
    }
    Constructor<?> c;
    try {
      c = solution.getConstructor(argTypes);
    } catch (NoSuchMethodException e) {
      throw argTypes.length == 0
          ? new SolutionException(e, "setup.needsNoArgs", name)
          : new SolutionException(e, "setup.needsConstructor", name, simpleNames(argTypes));
    }
    try {
      return type.cast(c.newInstance(args));
    } catch (InvocationTargetException e) {
      Throwable t = e.getCause();
      throw new SolutionException(
          t == null ? e : t, "setup.constructorThrew", name, t == null ? "?" : describe(t));
    } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
      throw new SolutionException(e, "setup.cannotCreate", name, e.toString());
    }
  }

  /** Separates the words that fill a sentence's holes in a set-up answer. */
  private static final char ARG = '\u001f';

  /**
   * The student's side's answer when their solution cannot be set up: the catalogue keys of the
   * check's name and of the message, and the words that fill the message's holes, so the grader
   * says it in the student's language.
   */
  public static String setUpAnswer(String nameKey, String messageKey, List<String> args) {
    StringBuilder sb = new StringBuilder(nameKey).append('\t').append(messageKey);
    for (String s : args) {
      sb.append(ARG).append(s.replace(ARG, ' '));
    }
    return sb.toString();
  }

  /** The message key and the words of a set-up answer's message part, split at the separator. */
  static List<String> fields(String s) {
    List<String> out = new ArrayList<>();
    int from = 0;
    for (int i = s.indexOf(ARG); i >= 0; i = s.indexOf(ARG, from)) {
      out.add(s.substring(from, i));
      from = i + 1;
    }
    out.add(s.substring(from));
    return out;
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
