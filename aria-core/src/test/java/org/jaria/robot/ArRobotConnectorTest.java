package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.jaria.clock.Clock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.ArSerialConnection;
import org.jaria.connection.ArTcpConnection;
import org.jaria.protocol.packets.StandardSip;
import org.jaria.testing.FakeRobot;
import org.jaria.testing.SocatPty;
import org.jaria.util.ArArgumentParser;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The connector's choices, against real sockets and a real tty (real time, a few seconds). */
class ArRobotConnectorTest {

  @TempDir Path dir;

  /** Serves a fake robot on {@code conn} until {@code stop}: answers, and sends SIPs when open. */
  private static Thread serve(ArDeviceConnection conn, AtomicBoolean stop) {
    Thread t =
        new Thread(
            () -> {
              FakeRobot fake = new FakeRobot(conn, Clock.system());
              StandardSip sip = new StandardSip();
              int x = 500;
              long nextSip = System.nanoTime();
              try {
                while (!stop.get()) {
                  if (!fake.pumpWait(20)) {
                    return;
                  }
                  if (fake.isOpen() && System.nanoTime() >= nextSip) {
                    x += 10; // the robot drives forward 10 mm per SIP
                    fake.sendSip(sip.setPos(x, 0, 0));
                    nextSip = System.nanoTime() + 100_000_000L;
                  }
                }
              } catch (IOException e) {
                // the client went away; the test checks what it needs
              }
            },
            "fake-robot");
    t.start();
    return t;
  }

  private static int unusedPort() throws IOException {
    try (ServerSocket s = new ServerSocket(0)) {
      return s.getLocalPort();
    }
  }

  @Test
  void remoteHostOptionConnectsOverTcp() throws Exception {
    AtomicBoolean stop = new AtomicBoolean();
    try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      Thread accept =
          new Thread(
              () -> {
                try {
                  Socket s = server.accept();
                  serve(ArTcpConnection.wrap(s, Clock.system()), stop).join();
                  s.close();
                } catch (IOException | InterruptedException e) {
                  Thread.currentThread().interrupt();
                }
              });
      accept.start();
      ArRobot robot = new ArRobot("tcp");
      ArArgumentParser args =
          new ArArgumentParser(
              new String[] {"-rh", "127.0.0.1", "-rrtp", String.valueOf(server.getLocalPort())});
      ArRobotConnector connector = new ArRobotConnector(args, robot);
      assertTrue(connector.parseArgs());
      assertTrue(args.checkHelpAndWarnUnparsed());
      assertTrue(connector.connectRobot(), robot.getConnectFailure());
      assertTrue(robot.getDeviceConnection() instanceof ArTcpConnection);
      robot.close();
      stop.set(true);
      accept.join(10_000);
    }
  }

  @Test
  void withoutOptionsASimulatorOnLocalhostIsTriedFirst() throws Exception {
    AtomicBoolean stop = new AtomicBoolean();
    try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      Thread accept =
          new Thread(
              () -> {
                try (Socket s = server.accept()) {
                  serve(ArTcpConnection.wrap(s, Clock.system()), stop).join();
                } catch (IOException | InterruptedException e) {
                  Thread.currentThread().interrupt();
                }
              },
              "accept-sim");
      accept.start();
      ArRobot robot = new ArRobot("sim first");
      ArRobotConnector connector =
          new ArRobotConnector(
              new ArArgumentParser(new String[] {"-rrtp", String.valueOf(server.getLocalPort())}),
              robot);
      assertTrue(connector.connectRobot(), robot.getConnectFailure());
      assertTrue(robot.getDeviceConnection() instanceof ArTcpConnection);
      assertTrue(robot.getDeviceConnection().getPortName().startsWith("tcp localhost"));
      robot.close();
      stop.set(true);
      accept.join(10_000);
    }
  }

  @Test
  void aPortThatWillNotOpenIsReportedWithWhatToDo() throws Exception {
    ArRobot robot = new ArRobot("nowhere");
    AtomicBoolean failedCb = new AtomicBoolean();
    robot.addFailedConnectCB(() -> failedCb.set(true));
    String port = dir.resolve("no-such-tty").toString();
    ArRobotConnector connector =
        new ArRobotConnector(new ArArgumentParser(new String[] {"-rp", port}), robot);
    assertFalse(connector.connectRobot());
    assertTrue(failedCb.get(), "the failed-connect callbacks ran");
    String why = robot.getConnectFailure();
    assertTrue(why.contains("could not open serial port " + port), why);
    assertTrue(why.contains("-rp"), "says how to pick another port: " + why);
    assertTrue(count(why, "-rp") == 1 && count(why, "ls /dev") == 1, "advice once: " + why);
  }

  /**
   * With no option at all the connector looks for a simulator on localhost first: when there is
   * none and the serial port fails too, the reason says both, and how to start a simulator.
   */
  @Test
  void withNoOptionsTheFailureSaysItLookedForASimulatorFirst() throws Exception {
    int simPort = unusedPort();
    ArRobot robot = new ArRobot("nowhere");
    ArRobotConnector connector =
        new ArRobotConnector(
            new ArArgumentParser(new String[] {"-rrtp", String.valueOf(simPort)}), robot);
    String tty = dir.resolve("no-such-tty").toString();
    connector.fallbackSerialPort = tty;
    assertFalse(connector.connectRobot());
    String why = robot.getConnectFailure();
    assertTrue(why.startsWith("no simulator on localhost:" + simPort), why);
    assertTrue(why.contains("./jaria sim"), why);
    assertTrue(why.contains("could not open serial port " + tty), why);
  }

  /** The same when the serial port opens but nothing answers on it (a PC's own /dev/ttyS0). */
  @Test
  void withNoOptionsASilentSerialPortStillSaysNoSimulatorFirst() throws Exception {
    try (SocatPty pty = new SocatPty(dir)) {
      int simPort = unusedPort();
      ArRobot robot = new ArRobot("silent");
      ArRobotConnector connector =
          new ArRobotConnector(
              new ArArgumentParser(new String[] {"-rrtp", String.valueOf(simPort)}), robot);
      connector.fallbackSerialPort = pty.a.toString();
      assertFalse(connector.connectRobot());
      String why = robot.getConnectFailure();
      assertTrue(why.startsWith("no simulator on localhost:" + simPort), why);
      assertTrue(why.contains("./jaria sim"), why);
      assertTrue(why.contains("tried the serial port " + pty.a + ": no robot is responding"), why);
      robot.close();
    }
  }

  @Test
  void nothingListeningAtTheRemoteHostIsSaidWithOneHint() throws Exception {
    ArRobot robot = new ArRobot("nowhere");
    int port = unusedPort();
    ArRobotConnector connector =
        new ArRobotConnector(
            new ArArgumentParser(new String[] {"-rh", "127.0.0.1", "-rrtp", "" + port}), robot);
    assertFalse(connector.connectRobot());
    String why = robot.getConnectFailure();
    assertTrue(why.startsWith("nothing accepts connections at 127.0.0.1:" + port), why);
    assertEquals(1, count(why, "jaria sim"), "the hint once: " + why);
  }

  private static int count(String s, String part) {
    int n = 0;
    for (int i = s.indexOf(part); i >= 0; i = s.indexOf(part, i + 1)) {
      n++;
    }
    return n;
  }

  @Test
  void withoutASimulatorTheSerialPortIsUsed() throws Exception {
    AtomicBoolean stop = new AtomicBoolean();
    try (SocatPty pty = new SocatPty(dir)) {
      ArSerialConnection robotSide = new ArSerialConnection(pty.b.toString(), 9600, Clock.system());
      robotSide.open();
      Thread server = serve(robotSide, stop);
      ArRobot robot = new ArRobot("serial");
      ArRobotConnector connector =
          new ArRobotConnector(
              new ArArgumentParser(
                  new String[] {"-rrtp", String.valueOf(unusedPort()), "-rp", pty.a.toString()}),
              robot);
      assertTrue(connector.connectRobot(), robot.getConnectFailure());
      assertTrue(robot.getDeviceConnection() instanceof ArSerialConnection);
      assertEquals("p3dx-sh", robot.getRobotSubType());
      CountDownLatch sawSip = new CountDownLatch(1);
      robot.addUserTask(
          "watch",
          1,
          () -> {
            // The first SIP fixes the origin; later ones move the robot.
            if (robot.getX() >= 10) {
              sawSip.countDown();
            }
          });
      robot.runAsync(true);
      assertTrue(sawSip.await(10, TimeUnit.SECONDS), "SIPs arrive through the tty");
      robot.close();
      assertFalse(robot.isRunning());
      stop.set(true);
      server.join(10_000);
      robotSide.close();
    }
  }

  @Test
  void missingValueMakesParseArgsFail() {
    ArRobotConnector c =
        new ArRobotConnector(new ArArgumentParser(new String[] {"-rb"}), new ArRobot());
    assertFalse(c.parseArgs());
    ArRobotConnector ok =
        new ArRobotConnector(new ArArgumentParser(new String[] {}), new ArRobot());
    assertTrue(ok.parseArgs());
    assertNull(ok.getRemoteHost());
    assertEquals(8101, ok.getRemotePort());
    assertTrue(ArRobotConnector.optionsHelp().contains("-remoteHost"));
  }
}
