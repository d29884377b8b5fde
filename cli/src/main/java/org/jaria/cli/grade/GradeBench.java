package org.jaria.cli.grade;

import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code jaria bench grade}: prints {@link GradeBenchmark}'s table. */
@Command(
    name = "grade",
    description =
        "Grading a class of 60 square submissions (good, starters, not compiling, hanging,"
            + " busy-waiting) with 2 jobs and with 1; the gradebooks must be the same.")
final class GradeBench implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(
      names = "--quick",
      description = "Shorter runs (fewer samples or shorter phases; less precise figures).")
  boolean quick;

  @Override
  public Integer call() throws Exception {
    spec.commandLine().getOut().println(GradeBenchmark.run(quick));
    return 0;
  }
}
