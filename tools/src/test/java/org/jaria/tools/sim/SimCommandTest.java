package org.jaria.tools.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.Writer;
import java.net.Socket;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.CommandCodec;
import org.jaria.sim.OdometryError;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

class SimCommandTest {

  @Test
  void optionsBuildTheWorldTheyDescribe() throws IOException {
    SimCommand cmd = new SimCommand();
    new CommandLine(cmd)
        .parseArgs(
            "--map",
            "hall",
            "--robot",
            "p3at-sh",
            "--robot",
            "amigo",
            "--robots",
            "4",
            "--port",
            "9000",
            "--speedup",
            "3",
            "--seed",
            "17",
            "--odometry-error",
            "random:0.02,0.05",
            "--sip-cycle",
            "50",
            "--watchdog-warn-only",
            "--no-specular",
            "--laser");
    SimOptions o = cmd.buildOptions();
    assertEquals(17, o.seed());
    assertEquals(9000, o.basePort());
    assertEquals(50, o.sipCycleMillis());
    assertTrue(o.watchdogWarnOnly());
    assertEquals(OdometryError.random(0.02, 0.05), o.odometryError());
    assertEquals(false, o.sonar().specular());
    assertEquals(3, cmd.pacing(), 1e-9);
    try (SimWorld w = cmd.createWorld()) {
      assertEquals(4, w.getRobots().size());
      assertEquals("p3at-sh", w.getRobot(0).getModel().getSubtype());
      assertEquals("amigo", w.getRobot(3).getModel().getSubtype());
      assertTrue(w.getRobot(0).view().laser() == null, "no scan before a client asks");
    }
  }

  @Test
  void badOptionsSayWhatIsWrong() {
    StringWriter err = new StringWriter();
    CommandLine cl = new CommandLine(new SimCommand()).setErr(new PrintWriter(err));
    int code = cl.execute("--map", "no-such-map", "--port", "0");
    assertTrue(code != 0);
    assertTrue(err.toString().contains("no-such-map"), err.toString());
    err.getBuffer().setLength(0);
    code = cl.execute("--robot", "r2d2", "--port", "0");
    assertTrue(code != 0);
    assertTrue(
        err.toString().contains("r2d2") && err.toString().contains("p3dx-sh"), err.toString());
    err.getBuffer().setLength(0);
    code = cl.execute("--odometry-error", "lots", "--port", "0");
    assertTrue(code != 0);
    assertTrue(err.toString().contains("random:T,R"), err.toString());
    err.getBuffer().setLength(0);
    code = cl.execute("--speedup", "2", "--lockstep", "--port", "0");
    assertTrue(code != 0);
    assertTrue(err.toString().contains("either"), err.toString());
  }

  /** Runs the command, connects like a client, and ends it with SIM_EXIT. */
  @Test
  void runsUntilAClientSendsSimExit() throws Exception {
    CountDownLatch ready = new CountDownLatch(1);
    StringBuilder text = new StringBuilder();
    Writer sink =
        new Writer() {
          @Override
          public void write(char[] c, int off, int len) {
            synchronized (text) {
              text.append(c, off, len);
              if (text.indexOf("Ctrl-C") >= 0) {
                ready.countDown();
              }
            }
          }

          @Override
          public void flush() {}

          @Override
          public void close() {}
        };
    SimCommand cmd = new SimCommand();
    CommandLine cl = new CommandLine(cmd).setOut(new PrintWriter(sink, true));
    AtomicInteger exit = new AtomicInteger(-1);
    Thread runner =
        new Thread(
            () -> exit.set(cl.execute("--port", "0", "--speedup", "4")), "jaria-test-sim-cli");
    runner.start();
    assertTrue(ready.await(20, TimeUnit.SECONDS), "the command prints where it listens");
    Matcher m;
    synchronized (text) {
      m = Pattern.compile("listening on TCP port (\\d+)").matcher(text);
      assertTrue(m.find(), text.toString());
    }
    int port = Integer.parseInt(m.group(1));
    try (Socket s = new Socket(java.net.InetAddress.getLoopbackAddress(), port)) {
      s.setSoTimeout(5000);
      OutputStream out = s.getOutputStream();
      DataInputStream in = new DataInputStream(s.getInputStream());
      ArRobotPacket p = new ArRobotPacket();
      for (int sync = 0; sync < 3; sync++) {
        CommandCodec.com(p, sync);
        out.write(p.getBuf(), 0, p.getLength());
        while (in.readUnsignedByte() != 0xFA) {
          // hunt for the header
        }
        in.readUnsignedByte();
        int count = in.readUnsignedByte();
        int id = in.readUnsignedByte();
        in.skipNBytes(count - 1);
        assertEquals(sync, id);
      }
      CommandCodec.comInt(p, ArCommands.OPEN.getNumber(), 1);
      out.write(p.getBuf(), 0, p.getLength());
      CommandCodec.comInt(p, ArCommands.SIM_EXIT.getNumber(), 3);
      out.write(p.getBuf(), 0, p.getLength());
      out.flush();
      runner.join(20_000);
    }
    assertEquals(3, exit.get(), "the exit code the client asked for");
    synchronized (text) {
      assertTrue(text.toString().contains("simulator stopped"));
    }
    assertTrue(!runner.isAlive());
  }

  @Test
  void robotsAreNamedAfterTheirModel() throws IOException {
    SimCommand cmd = new SimCommand();
    new CommandLine(cmd).parseArgs("--robots", "2", "--port", "0");
    try (SimWorld w = cmd.createWorld()) {
      SimRobot r = w.getRobot(1);
      assertEquals("p3dx-sh_2", r.getName());
    }
  }
}
