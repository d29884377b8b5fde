package org.jaria.tools.cli;

import java.util.Optional;
import java.util.ServiceLoader;
import org.jaria.desktop.spi.DesktopApps;
import org.jaria.tools.ProjectVersion;
import org.jaria.tools.desktop.Desktop;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The {@code jaria} command: one entry point for the simulator, the demos, the benchmarks, the
 * protocol tools, grading and the desktop apps. Run {@code ./jaria --help} for the list. Grading
 * ({@code jaria grade}) comes from the {@code cli} module through a {@link CommandProvider}; the
 * desktop apps (JavaFX) come from the {@code apps} module when it is on the class path, and are
 * stand-ins that say how to get them otherwise (see {@link Desktop}).
 */
@Command(
    name = "jaria",
    mixinStandardHelpOptions = true,
    versionProvider = JariaCli.Version.class,
    description = "JAria: Pioneer robots in pure Java (ARIA, ARCOS, a simulator, SonARNL, ACTS).",
    subcommands = {
      VersionCommand.class,
      PacketsCommand.class,
      org.jaria.tools.laser.LaserCommand.class,
      MapCommand.class,
      org.jaria.tools.sim.SimGuiCommand.class,
      org.jaria.tools.acts.ActsCommand.class,
      org.jaria.tools.demo.DemoCommand.class,
      org.jaria.tools.web.WebCommand.class,
      BenchCommand.class
    })
public final class JariaCli implements Runnable {

  @CommandLine.Spec CommandLine.Model.CommandSpec spec;

  @Override
  public void run() {
    spec.commandLine().usage(spec.commandLine().getOut());
  }

  /** Builds the command line with every subcommand, ready to execute. */
  public static CommandLine commandLine() {
    CommandLine cli = new CommandLine(new JariaCli());
    CommandLine bench = cli.getSubcommands().get("bench");
    for (CommandProvider more : ServiceLoader.load(CommandProvider.class)) {
      for (Object c : more.commands()) {
        add(cli, new CommandLine(c));
      }
      for (Object b : more.benchmarks()) {
        add(bench, new CommandLine(b));
      }
    }
    Optional<DesktopApps> apps = Desktop.find();
    for (CommandLine app : Desktop.appCommands(apps)) {
      add(cli, app);
    }
    for (CommandLine b : Desktop.benchCommands(apps)) {
      add(bench, b);
    }
    cli.addSubcommand(new CommandLine.HelpCommand());
    addHelpOptions(cli);
    cli.setParameterExceptionHandler(CliErrors::badArguments);
    cli.setExecutionExceptionHandler(CliErrors::failed);
    return cli;
  }

  private static void add(CommandLine parent, CommandLine sub) {
    parent.addSubcommand(sub.getCommandName(), sub);
  }

  /**
   * Gives every subcommand a {@code --help} (and {@code -h} where the command does not use it for
   * something else), so {@code jaria demo --help} shows the demo's usage. A command that has its
   * own {@code -h} for help (ACTS's and EZ-Train's options) gets {@code --help} as a second name of
   * that option, so the usage lists one help option, not two.
   */
  private static void addHelpOptions(CommandLine cl) {
    for (CommandLine sub : cl.getSubcommands().values()) {
      CommandLine.Model.CommandSpec spec = sub.getCommandSpec();
      if (spec.findOption("--help") == null) {
        CommandLine.Model.OptionSpec shortHelp = spec.findOption("-h");
        if (shortHelp == null) {
          spec.addOption(helpOption("-h", "--help"));
        } else if (shortHelp.usageHelp() && shortHelp.names().length == 1) {
          spec.remove(shortHelp);
          spec.addOption(shortHelp.toBuilder().names("-h", "--help").build());
        } else {
          spec.addOption(helpOption("--help"));
        }
      }
      addHelpOptions(sub);
    }
  }

  private static CommandLine.Model.OptionSpec helpOption(String... names) {
    return CommandLine.Model.OptionSpec.builder(names)
        .usageHelp(true)
        .description("Show this help message and exit.")
        .build();
  }

  /** Runs {@code jaria} with {@code args} and exits with its status. */
  public static void main(String[] args) {
    System.exit(commandLine().execute(args));
  }

  /** Supplies {@code --version}. */
  static final class Version implements CommandLine.IVersionProvider {
    @Override
    public String[] getVersion() {
      return new String[] {
        "JAria " + ProjectVersion.get(),
        "Java "
            + System.getProperty("java.version")
            + " ("
            + System.getProperty("java.vendor")
            + ")",
        "OS " + System.getProperty("os.name") + " " + System.getProperty("os.arch")
      };
    }
  }
}
