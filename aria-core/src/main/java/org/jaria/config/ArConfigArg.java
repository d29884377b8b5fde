package org.jaria.config;

import java.math.BigDecimal;
import java.util.Locale;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;

/**
 * One typed configuration parameter (ARIA's {@code ArConfigArg}): a name, a description, a type
 * (integer, real number, boolean or text), optional bounds and the current value. A module creates
 * its parameters, registers them with {@link ArConfig#addParam}, and reads the current value
 * whenever it needs it ({@link #getInt()}, {@link #getDouble()} ...); values may be read and set
 * from any thread.
 *
 * <pre>{@code
 * ArConfigArg triggerDist =
 *     ArConfigArg.ofDouble("TriggerDistance", 200, "mm moved before an update", 0, 10000);
 * triggerDist.addChangeListener(a -> log.info("now {}", a.getDouble()));
 * }</pre>
 *
 * <p>Setting a value outside the bounds, or of the wrong type, throws {@link
 * IllegalArgumentException} with a message that names the parameter and the allowed range; the old
 * value stays.
 */
public final class ArConfigArg {

  /** The kinds of value a parameter can hold. */
  public enum Type {
    /** A whole number ({@code int}). */
    INT,
    /** A real number ({@code double}). */
    DOUBLE,
    /** true or false. */
    BOOL,
    /** A line of text (without {@code ;}, which starts a comment in the file). */
    STRING
  }

  private final String name;
  private final String description;
  private final Type type;
  private final double min;
  private final double max;
  private final Object defaultValue;
  private volatile Object value;
  private volatile ArPriority priority = ArPriority.NORMAL;
  private final CopyOnWriteArrayList<Consumer<ArConfigArg>> listeners =
      new CopyOnWriteArrayList<>();

  private ArConfigArg(
      String name, String description, Type type, double min, double max, Object value) {
    this.name = checkName(name);
    this.description = description == null ? "" : description.replaceAll("\\p{Cntrl}", " ").strip();
    this.type = type;
    if (min > max) {
      throw new IllegalArgumentException(
          "parameter " + name + ": minimum " + min + " is above maximum " + max);
    }
    this.min = min;
    this.max = max;
    Object checked = check(value);
    this.defaultValue = checked;
    this.value = checked;
  }

  private static String checkName(String name) {
    Objects.requireNonNull(name, "a parameter needs a name");
    if (name.isEmpty() || (!isAsciiLetter(name.charAt(0)) && name.charAt(0) != '_')) {
      throw new IllegalArgumentException(
          "parameter name '" + name + "' must start with a letter (a-z, A-Z) or '_'");
    }
    for (int i = 0; i < name.length(); i++) {
      char c = name.charAt(i);
      if (!isAsciiLetter(c) && !(c >= '0' && c <= '9') && "_-.+".indexOf(c) < 0) {
        throw new IllegalArgumentException(
            "parameter name '"
                + name
                + "' may only contain letters, digits and _ - . + (it is one word in the file)");
      }
    }
    return name;
  }

  private static boolean isAsciiLetter(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
  }

  /** An integer parameter with bounds (inclusive). */
  public static ArConfigArg ofInt(String name, int value, String description, int min, int max) {
    return new ArConfigArg(name, description, Type.INT, min, max, value);
  }

  /** An integer parameter without bounds. */
  public static ArConfigArg ofInt(String name, int value, String description) {
    return ofInt(name, value, description, Integer.MIN_VALUE, Integer.MAX_VALUE);
  }

  /** A real-number parameter with bounds (inclusive). */
  public static ArConfigArg ofDouble(
      String name, double value, String description, double min, double max) {
    return new ArConfigArg(name, description, Type.DOUBLE, min, max, value);
  }

  /** A real-number parameter without bounds (any finite value). */
  public static ArConfigArg ofDouble(String name, double value, String description) {
    return ofDouble(name, value, description, -Double.MAX_VALUE, Double.MAX_VALUE);
  }

  /** A boolean parameter. */
  public static ArConfigArg ofBool(String name, boolean value, String description) {
    return new ArConfigArg(name, description, Type.BOOL, 0, 0, value);
  }

  /** A text parameter (one line, no {@code ;}). */
  public static ArConfigArg ofString(String name, String value, String description) {
    return new ArConfigArg(name, description, Type.STRING, 0, 0, value);
  }

  // ------------------------------------------------------------------ reading

  /** The parameter's name (one word, compared case-insensitively in files). */
  public String getName() {
    return name;
  }

  /** What the parameter means, for people. */
  public String getDescription() {
    return description;
  }

  /** The parameter's type. */
  public Type getType() {
    return type;
  }

  /** How important the parameter is (set when it is added to a config). */
  public ArPriority getPriority() {
    return priority;
  }

  void setPriority(ArPriority p) {
    priority = Objects.requireNonNull(p, "priority");
  }

  /** The value of an {@link Type#INT} parameter. */
  public int getInt() {
    requireType(Type.INT);
    return (Integer) value;
  }

  /** The value of a {@link Type#DOUBLE} (or {@link Type#INT}) parameter. */
  public double getDouble() {
    Object v = value;
    if (v instanceof Integer i) {
      return i;
    }
    requireType(Type.DOUBLE);
    return (Double) v;
  }

  /** The value of a {@link Type#BOOL} parameter. */
  public boolean getBool() {
    requireType(Type.BOOL);
    return (Boolean) value;
  }

  /** The value of a {@link Type#STRING} parameter. */
  public String getString() {
    requireType(Type.STRING);
    return (String) value;
  }

  /** Whether the parameter has a lower bound. */
  public boolean hasMin() {
    return switch (type) {
      case INT -> min > Integer.MIN_VALUE;
      case DOUBLE -> min > -Double.MAX_VALUE;
      case BOOL, STRING -> false;
    };
  }

  /** Whether the parameter has an upper bound. */
  public boolean hasMax() {
    return switch (type) {
      case INT -> max < Integer.MAX_VALUE;
      case DOUBLE -> max < Double.MAX_VALUE;
      case BOOL, STRING -> false;
    };
  }

  /** The lower bound of a number parameter. */
  public double getMin() {
    return min;
  }

  /** The upper bound of a number parameter. */
  public double getMax() {
    return max;
  }

  /** The current value as it is written in a file. */
  public String getValueText() {
    return format(value);
  }

  /** The value the parameter was created with, as text. */
  public String getDefaultText() {
    return format(defaultValue);
  }

  /** Whether the value differs from the one the parameter was created with. */
  public boolean isChanged() {
    return !value.equals(defaultValue);
  }

  // ------------------------------------------------------------------ setting

  /**
   * Sets an {@link Type#INT} parameter (or a {@link Type#DOUBLE} one).
   *
   * @return whether the value changed
   * @throws IllegalArgumentException if out of bounds or of the wrong type
   */
  public boolean setInt(int v) {
    return type == Type.DOUBLE ? set((double) v) : set(v);
  }

  /**
   * Sets a {@link Type#DOUBLE} parameter.
   *
   * @return whether the value changed
   * @throws IllegalArgumentException if out of bounds, not finite, or of the wrong type
   */
  public boolean setDouble(double v) {
    return set(v);
  }

  /**
   * Sets a {@link Type#BOOL} parameter.
   *
   * @return whether the value changed
   */
  public boolean setBool(boolean v) {
    return set(v);
  }

  /**
   * Sets a {@link Type#STRING} parameter.
   *
   * @return whether the value changed
   * @throws IllegalArgumentException if the text has {@code ;} or control characters
   */
  public boolean setString(String v) {
    return set(v);
  }

  /**
   * Sets the value from its text form, as in a file: whole numbers, real numbers ({@code 1.5},
   * {@code 2e3}), booleans ({@code true/false}, {@code 1/0}, {@code yes/no}, {@code on/off}).
   *
   * @return whether the value changed
   * @throws IllegalArgumentException saying what text was expected
   */
  public boolean setValueFromText(String text) {
    return set(parse(text));
  }

  /** Sets an already checked value (from {@link #parse}). */
  boolean setValueFromTyped(Object v) {
    return set(v);
  }

  /** Puts back the value the parameter was created with. */
  public boolean resetToDefault() {
    return set(defaultValue);
  }

  /**
   * Checks the text form of a value without setting it.
   *
   * @return the typed value
   * @throws IllegalArgumentException saying what text was expected
   */
  Object parse(String text) {
    String t = text == null ? "" : text.strip();
    switch (type) {
      case INT -> {
        try {
          return check(Integer.parseInt(t.startsWith("+") ? t.substring(1) : t));
        } catch (NumberFormatException e) {
          throw new IllegalArgumentException(
              "parameter " + name + " needs a whole number" + bounds() + ", not '" + t + "'", e);
        }
      }
      case DOUBLE -> {
        double d;
        try {
          d = Double.parseDouble(t);
        } catch (NumberFormatException e) {
          throw new IllegalArgumentException(
              "parameter " + name + " needs a number" + bounds() + ", not '" + t + "'", e);
        }
        return check(d);
      }
      case BOOL -> {
        switch (t.toLowerCase(Locale.ROOT)) {
          case "true", "1", "yes", "on" -> {
            return true;
          }
          case "false", "0", "no", "off" -> {
            return false;
          }
          default ->
              throw new IllegalArgumentException(
                  "parameter " + name + " needs true or false, not '" + t + "'");
        }
      }
      case STRING -> {
        return check(t);
      }
    }
    throw new AssertionError(type);
  }

  private boolean set(Object v) {
    Object checked = check(v);
    boolean changed;
    synchronized (this) {
      changed = !checked.equals(value);
      value = checked;
    }
    if (changed) {
      for (Consumer<ArConfigArg> l : listeners) {
        l.accept(this);
      }
    }
    return changed;
  }

  private Object check(Object v) {
    Objects.requireNonNull(v, () -> "parameter " + name + " cannot be set to null");
    switch (type) {
      case INT -> {
        if (!(v instanceof Integer i)) {
          throw wrongType(v);
        }
        if (i < min || i > max) {
          throw outOfBounds(i);
        }
        return i;
      }
      case DOUBLE -> {
        double d;
        if (v instanceof Double x) {
          d = x;
        } else if (v instanceof Integer x) {
          d = x;
        } else {
          throw wrongType(v);
        }
        if (!Double.isFinite(d)) {
          throw new IllegalArgumentException(
              "parameter " + name + " needs a finite number" + bounds() + ", not " + d);
        }
        if (d < min || d > max) {
          throw outOfBounds(d);
        }
        return d;
      }
      case BOOL -> {
        if (!(v instanceof Boolean)) {
          throw wrongType(v);
        }
        return v;
      }
      case STRING -> {
        if (!(v instanceof String s)) {
          throw wrongType(v);
        }
        for (int i = 0; i < s.length(); i++) {
          char c = s.charAt(i);
          if (c == ';' || (Character.isISOControl(c) && c != '\t') || c > 0xFF) {
            throw new IllegalArgumentException(
                "parameter "
                    + name
                    + ": text values cannot contain ';' (a comment in the file), control"
                    + " characters or characters outside Latin-1 (the file's encoding)");
          }
        }
        return s.strip();
      }
    }
    throw new AssertionError(type);
  }

  private IllegalArgumentException wrongType(Object v) {
    return new IllegalArgumentException(
        "parameter "
            + name
            + " is of type "
            + type
            + ", it cannot hold the "
            + v.getClass().getSimpleName()
            + " "
            + v);
  }

  private IllegalArgumentException outOfBounds(Object v) {
    return new IllegalArgumentException(
        "parameter " + name + " must be" + bounds() + "; " + format(v) + " is out of range");
  }

  private String bounds() {
    if (hasMin() && hasMax()) {
      return " between " + format(number(min)) + " and " + format(number(max));
    }
    if (hasMin()) {
      return " of at least " + format(number(min));
    }
    if (hasMax()) {
      return " of at most " + format(number(max));
    }
    return "";
  }

  private Object number(double d) {
    return type == Type.INT ? (Object) (int) d : (Object) d;
  }

  private static String format(Object v) {
    if (v instanceof Double d) {
      return BigDecimal.valueOf(d).stripTrailingZeros().toPlainString();
    }
    return String.valueOf(v);
  }

  /** A one-line description with bounds, as written after {@code ;} in a file. */
  public String getCommentText() {
    String b = bounds();
    if (b.isEmpty()) {
      return description;
    }
    String range = "(" + b.strip() + ")";
    return description.isEmpty() ? range : description + " " + range;
  }

  private void requireType(Type t) {
    if (type != t) {
      throw new IllegalStateException(
          "parameter " + name + " is of type " + type + ", not " + t + ": use get" + getterFor());
    }
  }

  private String getterFor() {
    return switch (type) {
      case INT -> "Int()";
      case DOUBLE -> "Double()";
      case BOOL -> "Bool()";
      case STRING -> "String()";
    };
  }

  // ------------------------------------------------------------------ listeners

  /**
   * Calls {@code listener} (on the thread that set the value) after every change of value. It must
   * return quickly.
   */
  public void addChangeListener(Consumer<ArConfigArg> listener) {
    listeners.add(Objects.requireNonNull(listener, "listener"));
  }

  /** Stops calling {@code listener}. */
  public void removeChangeListener(Consumer<ArConfigArg> listener) {
    listeners.remove(listener);
  }

  @Override
  public String toString() {
    return name + "=" + getValueText() + " (" + type + ")";
  }
}
