package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.net.ServerSocket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.parallel.Execution;
import org.junit.jupiter.api.parallel.ExecutionMode;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The getting-started guide's browser-only recipe run as a reader follows it, in English and
 * Spanish (apart from {@link GettingStartedRecipesTest}, so that the two run side by side).
 *
 * <p>The two guides' runs go side by side too (see junit-platform.properties): each starts its own
 * simulator on free ports and its own HelloRobot, and mostly waits on the robot's square.
 */
@Tag("slow")
@Execution(ExecutionMode.CONCURRENT)
class BrowserOnlyRecipeTest {

  private final GuideRecipes guides = new GuideRecipes();

  /**
   * The browser-only recipe as a reader follows it, in each guide: its {@code ./jaria sim ...
   * --web} line starts the simulator with the web view (a free port for the web view and the robot,
   * ten times real time), the printed address serves the page, a WebSocket client of that address
   * watches the robot's true pose as the page does, and step 3's HelloRobot line drives the square
   * that the watcher sees.
   */
  @ParameterizedTest
  @ValueSource(strings = {"docs/getting-started.md", "docs/es/primeros-pasos.md"})
  void theBrowserOnlyRecipeShowsTheSquareAsWritten(String guide) throws Exception {
    List<String> webLines =
        guides.guideLines(guide, "./jaria sim ").stream().filter(l -> l.contains("--web")).toList();
    assertEquals(1, webLines.size(), guide + " shows one simulator line with --web");
    List<String> javaLines =
        guides.guideLines(guide, "java -cp").stream()
            .filter(l -> l.contains("-rh localhost"))
            .toList();
    int port;
    try (ServerSocket s = new ServerSocket(0)) {
      port = s.getLocalPort();
    }
    List<String> sim = new ArrayList<>(ShellWords.split(webLines.get(0)));
    sim.remove(0);
    sim.add(sim.indexOf("--web") + 1, "0"); // any free port: the test must not need 8088
    sim.addAll(List.of("--port", String.valueOf(port), "--speedup", "10"));
    boolean stopped;
    GuideRecipes.Started simulator = GuideRecipes.start(sim, "guide-web");
    StringWriter simOut = simulator.out();
    try {
      GuideRecipes.waitForPort(port, simOut);
      long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
      while (!simOut.toString().contains("Web view: open")) {
        assertTrue(System.nanoTime() < deadline, "no web view address printed:\n" + simOut);
        // Watching another thread's printed output, which has no event to wait on.
        TimeUnit.MILLISECONDS.sleep(50);
      }
      java.util.regex.Matcher m =
          java.util.regex.Pattern.compile("Web view: open (http://\\S+) in a browser")
              .matcher(simOut.toString());
      assertTrue(m.find(), simOut.toString());
      java.net.URI page = java.net.URI.create(m.group(1));
      var http = java.net.http.HttpClient.newHttpClient();
      var body =
          http.send(
              java.net.http.HttpRequest.newBuilder(page).build(),
              java.net.http.HttpResponse.BodyHandlers.ofString());
      assertEquals(200, body.statusCode());
      assertTrue(body.body().contains("<canvas"), body.body());
      PoseWatcher watcher = PoseWatcher.open(page);
      try {
        GuideRecipes.HelloRobotRun run = guides.runHelloRobot(javaLines.get(0), port);
        assertTrue(run.done() && run.exit() == 0, "HelloRobot finished:\n" + run.out());
        assertTrue(
            watcher.farthestMm() > 800,
            "the web view saw the robot drive its square: " + watcher.farthestMm() + " mm");
      } finally {
        watcher.close();
      }
    } finally {
      stopped = simulator.stop();
    }
    assertTrue(stopped, "the simulator stopped");
  }
}
