package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.ServerSocket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.jaria.sim.RobotFactory;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.tools.cli.JariaCli;
import org.jaria.tools.sim.SimCommand;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * The robot-factory recipe of docs/simulator.md as a reader follows it: the {@code ./jaria sim -R
 * ...} line builds its world through the real command line (only a free port added), the two {@code
 * ./jaria demo wander --remote ...} lines run at the same time against it (cut to two seconds),
 * each drives a robot of its own, and when both are done only the {@code -r} robot is left.
 */
@Tag("slow")
class RobotFactoryRecipeTest {

  private static List<String> recipeLines(String prefix) throws IOException {
    List<String> out = new ArrayList<>();
    for (MarkdownBlocks.Block b : MarkdownBlocks.all(Repo.root())) {
      if (!b.file().toString().replace('\\', '/').endsWith("docs/simulator.md")) {
        continue;
      }
      for (String l : b.text().split("\n", -1)) {
        if (l.strip().startsWith(prefix)) {
          out.add(l.strip());
        }
      }
    }
    return out;
  }

  /** The simulator of the recipe's {@code ./jaria sim} line, its first port {@code port}. */
  private static SimWorld simulator(String simLine, int port) throws Exception {
    List<String> simArgs = new ArrayList<>(ShellWords.split(simLine));
    simArgs.subList(0, 2).clear(); // ./jaria sim
    simArgs.addAll(List.of("-p", String.valueOf(port)));
    SimCommand sim = new SimCommand();
    new CommandLine(sim).parseArgs(simArgs.toArray(String[]::new));
    return sim.createWorld();
  }

  @Test
  void twoProgramsOnTheFactoryPortEachDriveTheirOwnRobot() throws Exception {
    List<String> simLines = recipeLines("./jaria sim -R");
    assertEquals(1, simLines.size(), simLines.toString());
    List<String> clients = recipeLines("./jaria demo wander --remote localhost:8101");
    assertEquals(2, clients.size(), clients.toString());

    SimWorld listening = null;
    int port = 0;
    // The recipe's simulator takes two ports, the factory's and the next: a free port's neighbour
    // can be taken meanwhile (by another test's connection), so a port pair in use is tried again.
    for (int attempt = 1; listening == null; attempt++) {
      try (ServerSocket s = new ServerSocket(0)) {
        port = s.getLocalPort();
      }
      SimWorld world = simulator(simLines.get(0), port);
      try {
        world.listen();
        listening = world;
      } catch (IOException e) {
        world.close();
        if (attempt == 5 || !String.valueOf(e.getMessage()).contains("in use")) {
          throw e;
        }
      }
    }
    ExecutorService pool = Executors.newFixedThreadPool(2);
    try (SimWorld world = listening) {
      RobotFactory factory = world.getRobotFactories().get(0);
      assertEquals(port, factory.getPort(), "the factory has the first port");
      assertEquals(port + 1, world.findRobot("guard").orElseThrow().getPort(), "guard the next");
      CountDownLatch bothDriving = new CountDownLatch(1);
      world.addStepListener(
          () -> {
            List<SimRobot> own = factory.getRobots();
            if (own.size() == 2 && own.stream().allMatch(r -> Math.abs(r.getVel()) > 50)) {
              bothDriving.countDown();
            }
          });
      world.startRealTime(1);

      List<Future<String>> runs = new ArrayList<>();
      for (String line : clients) {
        List<String> words = new ArrayList<>(ShellWords.split(line));
        words.subList(0, 1).clear(); // ./jaria
        words.set(words.indexOf("localhost:8101"), "localhost:" + port);
        words.set(words.indexOf("--seconds") + 1, "4");
        runs.add(
            pool.submit(
                () -> {
                  StringWriter out = new StringWriter();
                  CommandLine cl = JariaCli.commandLine();
                  cl.setOut(new PrintWriter(out, true));
                  cl.setErr(new PrintWriter(out, true));
                  int exit = cl.execute(words.toArray(String[]::new));
                  return exit + "\n" + out;
                }));
      }
      assertTrue(bothDriving.await(60, TimeUnit.SECONDS), "two factory robots drove at once");
      for (Future<String> r : runs) {
        String result = r.get(60, TimeUnit.SECONDS);
        assertTrue(result.startsWith("0\n"), result);
      }
      CountDownLatch gone = new CountDownLatch(1);
      world.addStepListener(
          () -> {
            if (factory.getRobots().isEmpty()) {
              gone.countDown();
            }
          });
      assertTrue(gone.await(30, TimeUnit.SECONDS), "the factory's robots left with their clients");
      assertEquals(List.of("guard"), world.getRobots().stream().map(SimRobot::getName).toList());
    } finally {
      pool.shutdownNow();
    }
  }
}
