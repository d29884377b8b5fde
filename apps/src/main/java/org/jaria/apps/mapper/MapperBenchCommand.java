package org.jaria.apps.mapper;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code jaria bench mapper}: prints {@link MapperBenchmark}'s table. */
@Command(
    name = "mapper",
    description =
        "Map editor frame times (draw, and draw + pixels) while zooming and panning a"
            + " 60,000-point map, headless software rendering.")
public final class MapperBenchCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(
      names = "--quick",
      description = "Shorter runs (fewer samples or shorter phases; less precise figures).")
  boolean quick;

  @Option(
      names = "--map",
      paramLabel = "FILE",
      description = "Time this map instead of the generated 60,000-point floor plan.")
  Path map;

  @Override
  public Integer call() throws Exception {
    spec.commandLine().getOut().println(MapperBenchmark.run(map, quick ? 40 : 200));
    return 0;
  }
}
