package org.jaria.tools.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import org.jaria.map.MapFormatException;
import picocli.CommandLine;
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
    err.println(name + ": " + e.getMessage());
    if (!UnmatchedArgumentException.printSuggestions(e, err)) {
      err.println("Run '" + name + " --help' for its options.");
    }
    err.flush();
    return cmd.getCommandSpec().exitCodeOnInvalidInput();
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

  /** The message to show: the exception's own, else its cause's, else its kind. */
  static String message(Throwable e) {
    for (Throwable t = e; t != null; t = t.getCause()) {
      if (t.getMessage() != null && !t.getMessage().isBlank()) {
        return t.getMessage();
      }
    }
    return e.getClass().getSimpleName();
  }
}
