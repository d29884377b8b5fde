package org.jaria.tools.demo;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.charset.StandardCharsets;
import org.jaria.clock.Clock;
import org.jaria.connection.RobotAddress;
import org.jaria.tools.options.SecondsOption;
import picocli.CommandLine.Option;

/** Options every demo shares. */
class DemoOptions {
  @Option(
      names = "--map",
      description =
          "Bundled map (office, hall, columbia) or .map file (default: office; hall for chase).")
  String map = "office";

  @Option(
      names = "--robot",
      description = "Robot model (default: ${DEFAULT-VALUE}).",
      defaultValue = "p3dx-sh")
  String model = "p3dx-sh";

  @Option(
      names = "--seconds",
      description = "Stop after this many seconds (default: ${DEFAULT-VALUE}; 0: until Ctrl-C).",
      converter = SecondsOption.Whole.class,
      defaultValue = "30")
  int seconds = 30;

  @Option(
      names = "--seed",
      description = "Simulator seed (default: ${DEFAULT-VALUE}).",
      defaultValue = "1")
  long seed = 1;

  @Option(
      names = "--remote",
      paramLabel = "HOST[:PORT]|DEVICE",
      description =
          "Use this robot or simulator instead of an embedded one (port 8101 if absent; a serial"
              + " device such as /dev/ttyS0 or /dev/ttyUSB0@115200 for a robot on a serial port).")
  String remote;

  /** ARIA's connection options for --remote. */
  String[] remoteArgs() {
    return RobotAddress.parse(remote).toArgs();
  }

  /**
   * Checks the {@code --remote} address before the program starts, so a wrong one is said once, in
   * the user's own option names, instead of by every layer that tries: a serial port must open, a
   * host name must resolve. A TCP port is not tried with a connection of its own: MobileSim and
   * AMRISim take any connection for their one client, close their port while it lasts and, when it
   * ends, may move the robot to the next port (AMRISim does while the old one is in TIME_WAIT), so
   * the program's own connection would find nobody there. {@link #remoteFailed} explains a TCP
   * address that the program could not connect to.
   *
   * @throws IOException saying what failed and what to try
   */
  void checkRemote() throws IOException {
    RobotAddress a = RobotAddress.parse(remote);
    if (a.isSerial()) {
      a.open(Clock.system(), "--remote").close();
      return;
    }
    try {
      InetAddress.getByName(a.host());
    } catch (UnknownHostException e) {
      throw new IOException(
          "unknown host '" + a.host() + "' in --remote " + remote + ": give a name or address", e);
    }
  }

  /** How the thesis's programs begin the line that says no robot connected. */
  private static final String NO_ROBOT = "Could not connect to the robot: ";

  /**
   * What a demo's program says went wrong with {@code --remote} (it names ARIA's options, which a
   * demo does not take): kept here for {@link #remoteFailed} to explain once, in the demo's words.
   */
  private final ByteArrayOutputStream programErrors = new ByteArrayOutputStream();

  /** The stream to give a demo's program for what goes wrong. */
  PrintStream programErr() {
    return new PrintStream(programErrors, true, StandardCharsets.UTF_8);
  }

  /**
   * What a demo's {@code --remote} run returns: {@code status}, unless it is 1 (no robot), which is
   * then explained in the user's own option names.
   *
   * @throws IOException saying what did not answer at the address and what to do
   */
  int remoteFailed(int status) throws IOException {
    if (status != 1) {
      return status;
    }
    String said = programErrors.toString(StandardCharsets.UTF_8).strip();
    String why =
        said.startsWith(NO_ROBOT)
            ? said.substring(NO_ROBOT.length()).lines().findFirst().orElse("")
            : "";
    RobotAddress a = RobotAddress.parse(remote);
    if (a.isSerial()) {
      throw new IOException(
          "no robot answered on "
              + a
              + (why.isEmpty() ? "" : " (" + firstClause(why) + ")")
              + ": check the cable, that the robot is on, and its speed (--remote DEVICE@BAUD)");
    }
    throw new IOException(
        (why.startsWith("nothing accepts connections")
                ? "nothing accepts connections at " + a
                : a
                    + " did not answer as a robot"
                    + (why.isEmpty() ? "" : " (" + firstClause(why) + ")"))
            + ": start a simulator there (./jaria sim --port "
            + a.port()
            + ") or give --remote the robot's HOST:PORT");
  }

  /** A reason without the library's advice, which names ARIA's options rather than --remote. */
  private static String firstClause(String why) {
    int colon = why.indexOf(": ");
    return colon < 0 ? why : why.substring(0, colon);
  }
}
