package org.jaria.tools.laser;

import java.io.IOException;
import java.io.PrintWriter;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import org.jaria.clock.Clock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.ArSerialConnection;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.devices.DeviceFaults;
import org.jaria.sim.devices.DeviceTcpServer;
import org.jaria.sim.devices.EmulatedDevice;
import org.jaria.sim.devices.LaserSensor;
import org.jaria.sim.devices.Lms200Emulator;
import org.jaria.sim.devices.UrgEmulator;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code jaria laser emulate}: a simulated robot's laser, in one of the bundled maps, presented as
 * a real LMS-200 or URG on a serial port (one end of a socat pseudo-terminal pair) or a TCP port.
 */
@Command(
    name = "emulate",
    description = {
      "Present a simulated robot's laser as a real LMS-200 or URG on a serial pseudo-terminal"
          + " or a TCP port, to try 'jaria laser' or an ARIA program without hardware.",
      "Example (two terminals):",
      "  socat pty,raw,echo=0,link=/tmp/laserA pty,raw,echo=0,link=/tmp/laserB",
      "  jaria laser emulate --type lms2xx --device /tmp/laserB",
      "  jaria laser --port /tmp/laserA --type lms2xx"
    })
final class LaserEmulateCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(
      names = {"-t", "--type"},
      defaultValue = "lms2xx",
      description = "Laser type: lms2xx or urg (default: ${DEFAULT-VALUE}).")
  String type;

  @Option(
      names = "--device",
      description = "Serial device to answer on (the other end of a socat pty pair).")
  String device;

  @Option(names = "--tcp", description = "TCP port to answer on (loopback only), instead.")
  Integer tcpPort;

  @Option(
      names = "--map",
      defaultValue = "office",
      description = "Bundled map the robot stands in (default: ${DEFAULT-VALUE}).")
  String map;

  @Option(
      names = "--period",
      defaultValue = "100",
      description = "Time between scans, ms (default: ${DEFAULT-VALUE}).")
  long periodMs;

  @Option(
      names = "--drop-every",
      defaultValue = "0",
      description = "Lose every n-th byte sent, as a noisy line (0: none).")
  int dropEvery;

  @Option(
      names = "--answer-delay",
      defaultValue = "0",
      description = "Answer each request this late, ms, as a slow device.")
  long answerDelayMs;

  @Override
  public Integer call() throws IOException, InterruptedException {
    PrintWriter out = spec.commandLine().getOut();
    PrintWriter err = spec.commandLine().getErr();
    if ((device == null) == (tcpPort == null)) {
      err.println("give either --device PATH (a serial device or pty) or --tcp PORT");
      return 2;
    }
    String t = type.toLowerCase(Locale.ROOT);
    if (!t.equals("lms2xx") && !t.equals("urg")) {
      err.println("--type is lms2xx or urg, not '" + type + "'");
      return 2;
    }
    DeviceFaults faults =
        DeviceFaults.NONE.withDropEveryNthByte(dropEvery).withAnswerDelayMs(answerDelayMs);
    try (SimWorld world = SimWorld.bundled(map, SimOptions.defaults())) {
      SimRobot robot = world.addRobot(RobotOptions.of("p3dx-sh").withLaser(true));
      LaserSensor sensor = LaserSensor.of(robot);
      CountDownLatch forever = new CountDownLatch(1);
      if (device != null) {
        ArDeviceConnection c =
            new ArSerialConnection(device, t.equals("urg") ? 19200 : 9600, Clock.system());
        try (EmulatedDevice d = create(t, c, sensor, faults)) {
          d.start();
          out.println(t + " emulator on " + device + " (robot at " + robot.getTruePose() + ")");
          out.flush();
          while (d.isRunning()) {
            d.join(1000);
          }
          return 0;
        }
      }
      try (DeviceTcpServer server =
          new DeviceTcpServer(tcpPort, (c, i) -> create(t, c, sensor, faults))) {
        out.println(t + " emulator on TCP port " + server.getPort() + "; ctrl-C to stop");
        out.flush();
        forever.await();
      }
      return 0;
    }
  }

  private EmulatedDevice create(
      String t, ArDeviceConnection c, LaserSensor sensor, DeviceFaults faults) {
    return t.equals("urg")
        ? new UrgEmulator(c, sensor, faults, periodMs)
        : new Lms200Emulator(c, sensor, faults, periodMs);
  }
}
