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
    subcommands = {
      BenchCommand.Protocol.class,
      BenchCommand.Sim.class,
      BenchCommand.Arnl.class,
      BenchCommand.Actions.class,
      BenchCommand.Net.class,
      BenchCommand.Mapping.class,
      BenchCommand.Hostile.class,
      BenchCommand.Web.class
    })
final class BenchCommand implements Runnable {

  @Spec CommandSpec spec;

  @Override
  public void run() {
    spec.commandLine().usage(spec.commandLine().getOut());
  }

  /** A benchmark subcommand: runs, then prints the table it returns. */
  abstract static class Bench implements Callable<Integer> {

    @Spec CommandSpec spec;

    /** Runs the benchmark; returns its table. */
    abstract String table() throws Exception;

    @Override
    public Integer call() throws Exception {
      spec.commandLine().getOut().println(table());
      return 0;
    }
  }

  /** A benchmark with a shorter, less precise form. */
  abstract static class QuickBench extends Bench {

    @Option(
        names = "--quick",
        description = "Shorter runs (fewer samples or shorter phases; less precise figures).")
    boolean quick;
  }

  /** {@code jaria bench protocol}. */
  @Command(
      name = "protocol",
      description = "SIP decode and command encode rates, and SIP-to-command latency over TCP.")
  static final class Protocol extends QuickBench {
    @Override
    String table() throws Exception {
      return ProtocolBenchmark.run(quick);
    }
  }

  /** {@code jaria bench web}. */
  @Command(
      name = "web",
      description =
          "The web view under load: 10 clients at 10 Hz subscribed to everything; server CPU,"
              + " update latency, the robot cycle with and without it, bytes per client.")
  static final class Web extends QuickBench {
    @Override
    String table() throws Exception {
      return org.jaria.tools.bench.WebBenchmark.run(quick);
    }
  }

  /** {@code jaria bench sim}. */
  @Command(
      name = "sim",
      description = "Simulator real-time factors (1, 10, 100 robots) and sonar ray-cast cost.")
  static final class Sim extends Bench {
    @Override
    String table() {
      return org.jaria.tools.bench.SimBenchmark.run();
    }
  }

  /** {@code jaria bench arnl}. */
  @Command(
      name = "arnl",
      description =
          "Sonar and laser localization update time and accuracy, global localization, planning"
              + " and navigation success (fixed seeds).")
  static final class Arnl extends QuickBench {
    @Override
    String table() {
      return org.jaria.tools.bench.arnl.ArnlBenchmark.run(quick);
    }
  }

  /** {@code jaria bench actions}. */
  @Command(
      name = "actions",
      description = "Resolver and whole-cycle time with 20 active actions on a simulated P3-DX.")
  static final class Actions extends QuickBench {
    @Override
    String table() {
      return org.jaria.tools.bench.ActionsBenchmark.run(quick);
    }
  }

  /** {@code jaria bench net}. */
  @Command(
      name = "net",
      description =
          "Robot cycle time with 20 monitors at 10 Hz and a hostile client; a client that stops"
              + " reading.")
  static final class Net extends QuickBench {
    @Override
    String table() throws Exception {
      return org.jaria.tools.bench.NetBenchmark.run(quick);
    }
  }

  /** {@code jaria bench mapping}. */
  @Command(
      name = "mapping",
      description =
          "Maps built from laser logs on the simulator (odometry error on): path and wall"
              + " accuracy, coverage, build time against the log's duration, memory; then laser"
              + " localization and navigation on the built map (office 3 laps, hall, columbia, a"
              + " generated map).")
  static final class Mapping extends QuickBench {
    @Override
    String table() {
      return org.jaria.tools.bench.arnl.MappingBench.run(quick);
    }
  }

  /** {@code jaria bench hostile}. */
  @Command(
      name = "hostile",
      description =
          "Hostile clients on the simulator and ACTS ports: connections refused and dropped,"
              + " memory and threads before and after; reconnects right after a disconnect.")
  static final class Hostile extends QuickBench {
    @Override
    String table() throws Exception {
      return org.jaria.tools.bench.HostileBenchmark.run(quick);
    }
  }
}
