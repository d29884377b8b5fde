package org.jaria.cli.grade;

import java.util.List;
import org.jaria.tools.cli.CommandProvider;

/**
 * Adds {@code jaria grade} and {@code jaria bench grade} to the command line (registered in {@code
 * META-INF/services}, found by {@code JariaCli}).
 */
public final class GradingCommands implements CommandProvider {

  /** Called by {@link java.util.ServiceLoader}. */
  public GradingCommands() {}

  @Override
  public List<Object> commands() {
    return List.of(new GradeCommand());
  }

  @Override
  public List<Object> benchmarks() {
    return List.of(new GradeBench());
  }
}
