package org.jaria.tools.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jaria.map.MapFormatException;
import org.jaria.util.UserFiles;
import picocli.CommandLine;
import picocli.CommandLine.MissingParameterException;
import picocli.CommandLine.Model.ArgSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.ParseResult;
import picocli.CommandLine.UnmatchedArgumentException;

/**
 * How {@code jaria} reports a failure: once, on one line naming the command, with one hint, and no
 * stack trace for what is expected to go wrong (a bad option, a file that is not there or not a
 * map, a port in use, nothing listening). Anything else is a bug and keeps its stack trace.
 */
final class CliErrors {

  private CliErrors() {}

  /** A wrong option or value: the message and where to read about the options, not the usage. */
  static int badArguments(ParameterException e, String[] args) {
    CommandLine cmd = e.getCommandLine();
    PrintWriter err = cmd.getErr();
    String name = cmd.getCommandSpec().qualifiedName();
    if (e instanceof UnmatchedArgumentException u && !u.getUnmatched().isEmpty()) {
      String typed = u.getUnmatched().get(0);
      boolean option = typed.startsWith("-");
      boolean command = !option && !cmd.getSubcommands().isEmpty();
      err.println(
          name
              + ": "
              + (option
                  ? "unknown option '" + typed + "'"
                  : command ? "unknown command '" + typed + "'" : e.getMessage()));
      List<String> similar = Suggestions.similar(typed, names(cmd, option));
      err.println(
          similar.isEmpty()
              ? "Run '" + name + " --help' for its " + (command ? "commands." : "options.")
              : "Did you mean " + String.join(" or ", similar) + "?");
    } else {
      err.println(name + ": " + e.getMessage());
      String hint = e instanceof MissingParameterException m ? typoOfMissing(m, args) : null;
      if (hint == null && e instanceof MissingParameterException) {
        hint = typoOfKnown(cmd, args);
      }
      err.println(hint != null ? hint : "Run '" + name + " --help' for its options.");
    }
    err.flush();
    return cmd.getCommandSpec().exitCodeOnInvalidInput();
  }

  /**
   * "Did you mean" for a required option that is missing because it was mistyped (a command whose
   * unknown options go to something else, as {@code screenshot}'s go to the app), or for a mistyped
   * option of a command that also misses a required parameter (picocli reports the missing
   * parameter first, as {@code map build --otuput} without its log would), or null.
   */
  private static String typoOfMissing(MissingParameterException e, String[] args) {
    List<String> missing = new ArrayList<>();
    for (ArgSpec a : e.getMissing()) {
      if (a instanceof OptionSpec o) {
        missing.addAll(List.of(o.names()));
      }
    }
    List<String> known = names(e.getCommandLine(), true);
    for (String a : args) {
      String typed = a.contains("=") ? a.substring(0, a.indexOf('=')) : a;
      boolean negativeNumber = typed.length() > 1 && Character.isDigit(typed.charAt(1));
      if (!typed.startsWith("-")
          || negativeNumber
          || missing.contains(typed)
          || known.contains(typed)) {
        continue;
      }
      List<String> similar = Suggestions.similar(typed, missing);
      if (similar.isEmpty()) {
        similar = Suggestions.similar(typed, known);
      }
      if (!similar.isEmpty()) {
        return "Did you mean " + similar.get(0) + " (not " + typed + ")?";
      }
    }
    return null;
  }

  /**
   * "Did you mean" for a mistyped option that picocli did not report because a required parameter
   * is missing as well (the mistyped option is taken as that parameter's place), or null.
   */
  private static String typoOfKnown(CommandLine cmd, String[] args) {
    List<String> known = names(cmd, true);
    for (String a : args) {
      String typed = a.contains("=") ? a.substring(0, a.indexOf('=')) : a;
      if (typed.startsWith("--") && !known.contains(typed)) {
        List<String> similar = Suggestions.similar(typed, known);
        if (!similar.isEmpty()) {
          return "Did you mean " + similar.get(0) + " (not " + typed + ")?";
        }
      }
    }
    return null;
  }

  /** The visible option names (or subcommand names) of {@code cmd}, for suggestions. */
  private static List<String> names(CommandLine cmd, boolean options) {
    List<String> out = new ArrayList<>();
    if (options) {
      for (OptionSpec o : cmd.getCommandSpec().options()) {
        if (!o.hidden()) {
          out.addAll(List.of(o.names()));
        }
      }
    } else {
      cmd.getSubcommands()
          .forEach(
              (n, sub) -> {
                if (!sub.getCommandSpec().usageMessage().hidden()) {
                  out.add(n);
                }
              });
    }
    return out;
  }

  /** A command that failed while running. */
  static int failed(Exception e, CommandLine cmd, ParseResult parsed) throws Exception {
    if (!isExpected(e)) {
      throw e; // a bug: picocli prints the stack trace
    }
    PrintWriter err = cmd.getErr();
    err.println(cmd.getCommandSpec().qualifiedName() + ": " + message(e));
    err.flush();
    return 1;
  }

  /** Whether {@code e} is a failure a user can cause and fix (its message says how). */
  static boolean isExpected(Throwable e) {
    return e instanceof IOException
        || e instanceof UncheckedIOException
        || e instanceof MapFormatException
        || e instanceof IllegalArgumentException
        || e instanceof IllegalStateException;
  }

  /**
   * The message to show: the exception's own, else its cause's, else its kind. A file the system
   * would not open (whose own message is only its path) is explained as {@link UserFiles} does.
   */
  static String message(Throwable e) {
    for (Throwable t = e; t != null; t = t.getCause()) {
      if (t instanceof FileSystemException f && f.getFile() != null) {
        return fileProblem(f);
      }
      String m = t.getMessage();
      boolean wrapper = t.getCause() != null && t.getCause().toString().equals(m);
      if (m != null && !m.isBlank() && !wrapper) {
        return m;
      }
    }
    return e.getClass().getSimpleName();
  }

  /** A file that could not be opened, read or written, said with what to do. */
  private static String fileProblem(FileSystemException f) {
    Path file = Path.of(f.getFile()).toAbsolutePath().normalize();
    Path parent = file.getParent();
    if (f instanceof NoSuchFileException && parent != null && !Files.isDirectory(parent)) {
      return "there is no folder " + parent + " (for " + file.getFileName() + "): create it first";
    }
    if (f instanceof NoSuchFileException) {
      return UserFiles.problem(file).orElse("there is no file " + file);
    }
    if (f instanceof AccessDeniedException) {
      return "permission denied for " + file + ": check its permissions (ls -l)";
    }
    return file + ": " + (f.getReason() == null ? f.getClass().getSimpleName() : f.getReason());
  }
}
