package org.jaria.config;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * A named group of parameters in an {@link ArConfig} ("Localization", "Path planning" ...), written
 * as {@code Section <name>} in a file. Parameter names are unique within a section, compared
 * case-insensitively. Obtain sections from {@link ArConfig}; they are safe to read from any thread.
 */
public final class ArConfigSection {

  private final String name;
  private volatile String comment;
  private final List<ArConfigArg> params = new ArrayList<>();

  ArConfigSection(String name, String comment) {
    this.name = name;
    this.comment = comment == null ? "" : comment.strip();
  }

  /** The section's name. */
  public String getName() {
    return name;
  }

  /** What the section is about (written as a comment under its header). */
  public String getComment() {
    return comment;
  }

  void setComment(String c) {
    if (c != null && !c.isBlank()) {
      comment = c.strip();
    }
  }

  /** The section's parameters in the order they were added (a copy). */
  public List<ArConfigArg> getParams() {
    synchronized (params) {
      return List.copyOf(params);
    }
  }

  /** The parameter called {@code paramName} (case-insensitive). */
  public Optional<ArConfigArg> findParam(String paramName) {
    String key = paramName.toLowerCase(Locale.ROOT);
    synchronized (params) {
      for (ArConfigArg a : params) {
        if (a.getName().toLowerCase(Locale.ROOT).equals(key)) {
          return Optional.of(a);
        }
      }
    }
    return Optional.empty();
  }

  void add(ArConfigArg arg) {
    synchronized (params) {
      params.add(arg);
    }
  }

  boolean remove(String paramName) {
    String key = paramName.toLowerCase(Locale.ROOT);
    synchronized (params) {
      return params.removeIf(a -> a.getName().toLowerCase(Locale.ROOT).equals(key));
    }
  }

  /** Whether {@code other} is the same section name (case-insensitive). */
  boolean isNamed(String other) {
    return name.equalsIgnoreCase(other.strip());
  }

  /** All parameters' current values, for quick looks in logs. */
  @Override
  public String toString() {
    List<String> parts = new ArrayList<>();
    for (ArConfigArg a : getParams()) {
      parts.add(a.getName() + "=" + a.getValueText());
    }
    return "Section " + name + " " + parts;
  }
}
