package org.jaria.tools.cli;

import java.util.concurrent.Callable;
import org.jaria.tools.bench.ProtocolBenchmark;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code jaria bench ...}: benchmarks that print a table of measured figures. */
@Command(
    name = "bench",
    description = "Run a benchmark and print its table of figures.",
    subcommands = {BenchCommand.Protocol.class})
final class BenchCommand implements Runnable {

  @Spec CommandSpec spec;

  @Override
  public void run() {
    spec.commandLine().usage(spec.commandLine().getOut());
  }

  /** {@code jaria bench protocol}. */
  @Command(
      name = "protocol",
      description = "SIP decode and command encode rates, and SIP-to-command latency over TCP.")
  static final class Protocol implements Callable<Integer> {

    @Spec CommandSpec spec;

    @Option(names = "--quick", description = "Shorter runs (less precise).")
    boolean quick;

    @Override
    public Integer call() throws Exception {
      spec.commandLine().getOut().println(ProtocolBenchmark.run(quick));
      return 0;
    }
  }
}
