package org.jaria.apps.simview;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import javafx.scene.control.ComboBox;
import javafx.stage.Stage;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.FxRuntime;
import org.jaria.apps.fx.ScriptedPrompts;
import org.jaria.sim.RobotFactory;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.testfx.api.FxRobot;
import org.testfx.framework.junit5.ApplicationExtension;
import org.testfx.framework.junit5.Start;

/**
 * The simulator view with a robot factory ({@code jaria sim --gui -R MODEL}): robots come and go
 * with their clients, and the view's Robot list and the canvas's per-robot state follow them. The
 * world is stepped by hand (virtual time); the clients are real TCP sockets.
 */
@Tag("gui")
@ExtendWith(ApplicationExtension.class)
class SimViewFactoryRobotsTest {

  private final ScriptedPrompts prompts = new ScriptedPrompts();
  private SimWorld world;
  private RobotFactory factory;
  private SimViewWindow window;

  @Start
  void start(Stage stage) throws IOException {
    world = SimWorld.bundled("office", SimOptions.builder().seed(3).basePort(0).build());
    world.addRobot(RobotOptions.of("p3dx-sh").withName("resident"));
    factory = world.addRobotFactory(RobotOptions.of("p3dx-sh"), 0, null);
    world.listen();
    window = new SimViewWindow(stage, AppEnvironment.scripted(prompts), world, 1, true);
    window.show(true);
  }

  @AfterEach
  void close() {
    FxRuntime.run(() -> window.stage().hide(), 10);
    FxRuntime.run(window::close, 10);
  }

  /**
   * Steps the paused world one tick at a time until {@code done} (the sockets' bytes and closes
   * reach the world between ticks); fails after 20 s of real time.
   */
  private void stepUntil(BooleanSupplier done, String what) {
    long giveUp = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
    while (!done.getAsBoolean()) {
      assertTrue(System.nanoTime() < giveUp, "never happened: " + what);
      world.step();
    }
  }

  private Socket connect() throws IOException {
    Socket s = new Socket();
    s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), factory.getPort()), 5000);
    return s;
  }

  private List<String> robotList() {
    return FxRuntime.call(
        () -> {
          window.canvas().refresh();
          return window.robotChoices().stream().map(SimViewWindow.RobotChoice::name).toList();
        },
        10);
  }

  private Set<Integer> remembered() {
    return FxRuntime.call(() -> window.canvas().rememberedRobots(), 10);
  }

  private static Set<Integer> numbers(List<SimRobot> robots) {
    Set<Integer> out = new HashSet<>();
    for (SimRobot r : robots) {
      out.add(r.getIndex());
    }
    return out;
  }

  @Test
  void aFactoryRobotJoinsTheRobotListAndLeavesItWithItsClient(FxRobot fx) throws Exception {
    window.ready().get(10, TimeUnit.SECONDS);
    assertEquals(List.of("resident"), robotList());
    String name;
    try (Socket client = connect()) {
      stepUntil(() -> factory.getRobotsMade() == 1, "the client gets a robot");
      name = "127.0.0.1:" + client.getLocalPort();
      assertEquals(List.of("resident", name), robotList());
      FxRuntime.run(
          () -> fx.lookup("#robot").<ComboBox<?>>query().getSelectionModel().select(1), 10);
    }
    stepUntil(() -> world.getRobots().size() == 1, "the client's robot leaves");
    assertEquals(List.of("resident"), robotList());
    assertEquals(
        "resident",
        FxRuntime.call(
                () ->
                    fx.lookup("#robot").<ComboBox<?>>query().getSelectionModel().getSelectedItem(),
                10)
            .toString(),
        "the selection falls back to a robot that is there");
    assertFalse(robotList().contains(name));
  }

  @Test
  void aFloodOfClientsLeavesNothingBehindInTheCanvas() throws Exception {
    window.ready().get(10, TimeUnit.SECONDS);
    int rounds = 8;
    int perRound = 5;
    for (int round = 0; round < rounds; round++) {
      List<Socket> clients = new ArrayList<>();
      try {
        for (int i = 0; i < perRound; i++) {
          Socket s = connect();
          clients.add(s);
          if (i % 2 == 1) {
            s.getOutputStream().write(new byte[] {(byte) 0xFA, (byte) 0xFB, 3, 0, 0, 0}); // SYNC0
          }
        }
        long expected = (long) (round + 1) * perRound;
        stepUntil(() -> factory.getRobotsMade() == expected, "every client gets a robot");
        assertEquals(1 + perRound, robotList().size(), "the list shows them all");
        assertEquals(numbers(world.getRobots()), remembered());
      } finally {
        for (Socket s : clients) {
          s.close();
        }
      }
      stepUntil(() -> world.getRobots().size() == 1, "their robots leave");
    }
    assertEquals(List.of("resident"), robotList());
    assertEquals(
        numbers(world.getRobots()),
        remembered(),
        "only the robot still there is remembered, after " + rounds * perRound + " came and went");
    assertEquals(1, FxRuntime.call(() -> window.canvas().snapshot().robots().size(), 10));
  }
}
