package org.jaria.apps.monitor;

import java.io.PrintWriter;
import java.util.concurrent.Callable;
import javafx.stage.Stage;
import org.jaria.apps.fx.AppCommand;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.AppLauncher;
import org.jaria.apps.fx.DesktopApp;
import org.jaria.net.protocol.Protocol;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code jaria monitor [host:port]}: watch and command a robot served by a guiServer ({@code jaria
 * demo guiserver}), as MobileEyes does. Several monitors may watch one robot.
 */
@Command(
    name = "monitor",
    mixinStandardHelpOptions = true,
    sortOptions = false,
    // One paragraph per element: picocli wraps each to the terminal's width by itself.
    description = {
      "The robot monitor (MobileEyes) for a guiServer (./jaria demo guiserver).",
      "Map, robot, sonar, particles and path; click to send the robot somewhere, drag it to"
          + " relocalize, drive it with the arrow keys; status, information strings,"
          + " configuration, camera and custom commands."
    })
public final class MonitorCommand implements Callable<Integer>, AppCommand {

  @Spec CommandSpec spec;

  @Parameters(
      index = "0",
      arity = "0..1",
      paramLabel = "HOST[:PORT]",
      description = "The guiServer (default 127.0.0.1:" + Protocol.DEFAULT_PORT + ").")
  String address = "127.0.0.1";

  @Option(names = "--user", description = "User name (for servers that need a login).")
  String user = "";

  @Option(
      names = "--password",
      description =
          "Password (visible to other users of this computer: prefer --password-file or the"
              + " JARIA_NET_PASSWORD environment variable).")
  String password;

  @Option(
      names = "--password-file",
      paramLabel = "FILE",
      description = "Read the password from the first line of FILE (which only you may read).")
  java.nio.file.Path passwordFile;

  @Override
  public String appName() {
    return "monitor";
  }

  /** Host of {@code address}. */
  String host() {
    int c = address.lastIndexOf(':');
    return c < 0 ? address : address.substring(0, c);
  }

  /**
   * Port of {@code address}.
   *
   * @throws IllegalArgumentException if it is not a number
   */
  int port() {
    int c = address.lastIndexOf(':');
    if (c < 0) {
      return Protocol.DEFAULT_PORT;
    }
    try {
      int p = Integer.parseInt(address.substring(c + 1));
      if (p < 1 || p > 65535) {
        throw new NumberFormatException("out of range");
      }
      return p;
    } catch (NumberFormatException e) {
      throw new IllegalArgumentException(
          "the address must be HOST or HOST:PORT with a port 1..65535, not '" + address + "'", e);
    }
  }

  @Override
  public DesktopApp open(Stage stage, AppEnvironment env) {
    String secret;
    try {
      secret = org.jaria.net.client.Passwords.resolve(password, passwordFile, System.getenv());
    } catch (java.io.IOException e) {
      throw new IllegalArgumentException(e.getMessage(), e);
    }
    MonitorWindow w = new MonitorWindow(stage, env, host(), port(), user, secret);
    w.show();
    return w;
  }

  @Override
  public Integer call() {
    PrintWriter err = spec.commandLine().getErr();
    try {
      port();
      org.jaria.net.client.Passwords.resolve(password, passwordFile, System.getenv());
    } catch (IllegalArgumentException | java.io.IOException e) {
      err.println("monitor: " + e.getMessage());
      return 2;
    }
    return AppLauncher.runUntilClosed(this, err);
  }
}
