package org.jaria.tools.cli;

import java.util.List;

/**
 * Commands that a module built after this one adds to {@code jaria}: {@link JariaCli} finds every
 * implementation on the class path with {@link java.util.ServiceLoader}. {@code jaria grade} comes
 * this way from the module {@code cli}: grading needs the classroom module, and this module ({@code
 * tools}) does not depend on it, so that the two build and run their tests side by side. The {@code
 * ./jaria} launcher runs the command line from {@code cli}, which has both.
 */
public interface CommandProvider {

  /** Top-level commands (picocli command objects), listed by {@code jaria --help} in this order. */
  List<Object> commands();

  /** {@code jaria bench} subcommands (picocli command objects). */
  List<Object> benchmarks();
}
