package org.jaria.tools.demo;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
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
   * Checks that the {@code --remote} robot can be reached before the program starts, so a wrong
   * address is said once, in the user's own option names, instead of by every layer that tries.
   *
   * @throws IOException saying what failed and what to try
   */
  void checkRemote() throws IOException {
    RobotAddress a = RobotAddress.parse(remote);
    if (a.isSerial()) {
      a.open(Clock.system(), "--remote").close();
      return;
    }
    try (Socket s = new Socket()) {
      s.connect(new InetSocketAddress(a.host(), a.port()), 3000);
    } catch (IOException e) {
      throw new IOException(
          "nothing accepts connections at "
              + a
              + " ("
              + e.getMessage()
              + "): start a simulator there (./jaria sim --port "
              + a.port()
              + ") or give --remote the robot's HOST:PORT",
          e);
    }
  }
}
