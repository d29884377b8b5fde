package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.net.ServerSocket;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The getting-started guide's recipes run as a reader follows them, in English and Spanish: the
 * simulator started by the guide's own {@code ./jaria sim} line, and the guide's {@code java} line
 * running the HelloRobot sample against it over TCP. (Classes of their own, this one, {@link
 * BrowserOnlyRecipeTest} and {@link DocsCommandsTest}, so that the build's test JVMs run them side
 * by side.)
 */
@Tag("slow")
class GettingStartedRecipesTest {

  private final GuideRecipes guides = new GuideRecipes();

  /**
   * The getting-started recipe as a reader follows it, in each guide (English and Spanish): step
   * 2's {@code ./jaria sim ...} line starts the simulator through the real command line (the same
   * map; only a free port and ten times real time added), and step 3's {@code java -cp
   * "tools/target/jaria-tools.jar:tools/target/lib/*" HelloRobot.java -rh localhost} runs the
   * sample as a single source file against it over TCP and must finish the square. Before {@code
   * package} has built the launcher's jars, this JVM's own class path stands in for them.
   */
  @ParameterizedTest
  @ValueSource(strings = {"docs/getting-started.md", "docs/es/primeros-pasos.md"})
  void theGettingStartedRecipeDrivesTheSquareAsWritten(String guide) throws Exception {
    List<String> simLines = guides.guideLines(guide, "./jaria sim ");
    List<String> headless =
        simLines.stream().filter(l -> !l.contains("--gui") && !l.contains("--web")).toList();
    assertEquals(1, headless.size(), guide + " shows one headless simulator line: " + simLines);
    List<String> javaLines =
        guides.guideLines(guide, "java -cp").stream()
            .filter(l -> l.contains("-rh localhost"))
            .toList();
    assertEquals(1, javaLines.size(), guide + " shows how to run HelloRobot.java: " + javaLines);

    int port;
    try (ServerSocket s = new ServerSocket(0)) {
      port = s.getLocalPort();
    }
    List<String> sim = new ArrayList<>(ShellWords.split(headless.get(0)));
    sim.remove(0);
    sim.addAll(List.of("--port", String.valueOf(port), "--speedup", "10"));
    boolean stopped;
    GuideRecipes.Started simulator = GuideRecipes.start(sim, "guide-simulator");
    StringWriter simOut = simulator.out();
    try {
      GuideRecipes.waitForPort(port, simOut);
      GuideRecipes.HelloRobotRun run = guides.runHelloRobot(javaLines.get(0), port);
      assertTrue(run.done(), "HelloRobot finished:\n" + run.out());
      assertEquals(0, run.exit(), run.out());
      assertTrue(run.out().contains("Connected to"), run.out());
      assertTrue(run.out().contains("Done; the robot believes it is at"), run.out());
    } finally {
      stopped = simulator.stop();
    }
    assertTrue(stopped, "the simulator stopped");
  }
}
