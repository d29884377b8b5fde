package org.jaria.apps.bench;

import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code jaria bench vision}: prints {@link VisionBenchmark}'s table (it needs OpenCV). */
@Command(
    name = "vision",
    description = "Blob tracking per frame at three sizes and 1/8/32 channels, against OpenCV.")
public final class VisionBenchCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(
      names = "--quick",
      description = "Shorter runs (fewer samples or shorter phases; less precise figures).")
  boolean quick;

  @Override
  public Integer call() throws Exception {
    spec.commandLine().getOut().println(VisionBenchmark.run(quick));
    return 0;
  }
}
