package org.jaria.tools.demo;

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
}
