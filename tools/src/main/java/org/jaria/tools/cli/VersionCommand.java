package org.jaria.tools.cli;

import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code jaria version}: what is running, on what. */
@Command(name = "version", description = "Print the JAria, Java and OS versions.")
final class VersionCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Override
  public Integer call() {
    for (String line : new JariaCli.Version().getVersion()) {
      spec.commandLine().getOut().println(line);
    }
    return 0;
  }
}
