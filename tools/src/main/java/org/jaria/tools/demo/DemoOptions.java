package org.jaria.tools.demo;

import java.io.IOException;
import java.net.InetAddress;
import java.net.UnknownHostException;
import org.jaria.clock.Clock;
import org.jaria.connection.RobotAddress;
import picocli.CommandLine.Option;

/** Options every demo shares. */
class DemoOptions {
  @Option(
      names = "--map",
      description = "Bundled map (office, hall) or .map file (default: office; hall for chase).")
  String map = "office";

  @Option(
      names = "--robot",
      description = "Robot model (default: ${DEFAULT-VALUE}).",
      defaultValue = "p3dx-sh")
  String model = "p3dx-sh";

  @Option(
      names = "--seconds",
      description =
          "Stop after this many seconds (default: ${DEFAULT-VALUE}; 0 runs until Ctrl-C).",
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

  /**
   * What a demo's {@code --remote} run returns: {@code status}, unless it is 1 (no robot) for a TCP
   * address, which is then explained in the user's own option names.
   *
   * @throws IOException saying that nothing answered at the address and what to do
   */
  int remoteFailed(int status) throws IOException {
    RobotAddress a = RobotAddress.parse(remote);
    if (status != 1 || a.isSerial()) {
      return status;
    }
    throw new IOException(
        "nothing accepts connections at "
            + a
            + ", or it did not answer as a robot: start a simulator there (./jaria sim --port "
            + a.port()
            + ") or give --remote the robot's HOST:PORT");
  }
}
