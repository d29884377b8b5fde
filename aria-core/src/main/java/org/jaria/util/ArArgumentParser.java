package org.jaria.util;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * Command-line arguments that several parts of a program pick from (ARIA's {@code
 * ArArgumentParser}): each part takes the options it knows, and whatever is left at the end is an
 * error the user should hear about.
 *
 * <pre>{@code
 * ArArgumentParser parser = new ArArgumentParser(args);
 * ArRobotConnector connector = new ArRobotConnector(parser, robot);
 * if (!connector.parseArgs() || !parser.checkHelpAndWarnUnparsed()) {
 *   connector.logOptions();
 *   System.exit(1);
 * }
 * }</pre>
 */
public final class ArArgumentParser {

  private final List<String> args;
  private boolean helpRequested;

  /** A parser over a copy of {@code args}. */
  public ArArgumentParser(String[] args) {
    this.args = new ArrayList<>(Arrays.asList(args));
  }

  /**
   * Adds arguments from the environment variable {@code JARIA_ARGS} (or ARIA's {@code ARIAARGS})
   * before the program's own, so command-line arguments win.
   */
  public void loadDefaultArguments() {
    String env = System.getenv("JARIA_ARGS");
    if (env == null) {
      env = System.getenv("ARIAARGS");
    }
    if (env != null && !env.isBlank()) {
      args.addAll(0, Arrays.asList(env.trim().split("\\s+")));
    }
  }

  /**
   * Takes a flag: returns whether any of {@code names} (e.g. "-help", "-h") was given, and removes
   * it. Names are compared without case.
   */
  public boolean checkArgument(String... names) {
    boolean found = false;
    for (int i = args.size() - 1; i >= 0; i--) {
      if (matches(args.get(i), names)) {
        args.remove(i);
        found = true;
      }
    }
    return found;
  }

  /**
   * Takes an option with a value: returns the value following the last of {@code names}, or null if
   * the option was not given. Both are removed.
   *
   * @throws IllegalArgumentException if the option is last, with no value after it
   */
  public String checkParameterArgument(String... names) {
    String value = null;
    for (int i = 0; i < args.size(); i++) {
      if (matches(args.get(i), names)) {
        if (i + 1 >= args.size()) {
          throw new IllegalArgumentException("option " + args.get(i) + " needs a value after it");
        }
        value = args.get(i + 1);
        args.remove(i + 1);
        args.remove(i);
        i--;
      }
    }
    return value;
  }

  /**
   * Takes an integer option; {@code fallback} if absent.
   *
   * @throws IllegalArgumentException if the value is not an integer
   */
  public int checkParameterArgumentInteger(int fallback, String... names) {
    String v = checkParameterArgument(names);
    if (v == null) {
      return fallback;
    }
    try {
      return Integer.parseInt(v);
    } catch (NumberFormatException e) {
      throw new IllegalArgumentException(
          "option " + names[0] + " needs a whole number, got '" + v + "'", e);
    }
  }

  /** Takes -help / -h / --help; returns whether help was asked for (remembered). */
  public boolean checkHelp() {
    if (checkArgument("-help", "-h", "--help", "/?")) {
      helpRequested = true;
    }
    return helpRequested;
  }

  /** Whether help was asked for. */
  public boolean isHelpRequested() {
    return helpRequested;
  }

  /**
   * Returns true if the program may go on: no help was asked for and every argument was taken.
   * Unused arguments are reported on standard error.
   */
  public boolean checkHelpAndWarnUnparsed() {
    if (checkHelp()) {
      return false;
    }
    if (!args.isEmpty()) {
      System.err.println("Unknown arguments: " + String.join(" ", args));
      return false;
    }
    return true;
  }

  /** The arguments nobody has taken yet. */
  public List<String> getUnparsed() {
    return List.copyOf(args);
  }

  private static boolean matches(String arg, String[] names) {
    for (String n : names) {
      if (arg.toLowerCase(Locale.ROOT).equals(n.toLowerCase(Locale.ROOT))) {
        return true;
      }
    }
    return false;
  }
}
