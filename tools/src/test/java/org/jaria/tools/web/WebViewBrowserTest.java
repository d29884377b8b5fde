package org.jaria.tools.web;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimRobot;
import org.jaria.simguiserver.SimulatedGuiServer;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * {@code jaria web --allow-control} in a real headless Chromium: the page loads with no console
 * error, draws the robot where the simulator has it, drives it with an arrow key, sends it to a
 * clicked goal that it reaches, and its screenshot shows the robot and the walls. The screenshot is
 * the README's picture ({@code target/web-view.png}).
 */
@Tag("slow")
class WebViewBrowserTest {

  static final Pattern URL = Pattern.compile("Web view: open (http://\\S+) in a browser");

  @Test
  void aBrowserWatchesDrivesAndSendsTheRobotToAGoal() throws Exception {
    StringWriter log = new StringWriter();
    WebCommand cmd = new WebCommand();
    CompletableFuture<SimulatedGuiServer> started = new CompletableFuture<>();
    cmd.onStarted = (s, v) -> started.complete(s);
    CommandLine cl = new CommandLine(cmd);
    cl.setOut(new PrintWriter(log, true));
    cl.setErr(new PrintWriter(log, true));
    Thread server =
        new Thread(
            () -> cl.execute("--port", "0", "--allow-control", "--speed", "4", "--seconds", "300"),
            "web-command");
    server.start();
    try (Chromium chrome = Chromium.start(1400, 860)) {
      SimulatedGuiServer sim = started.get(120, TimeUnit.SECONDS);
      Matcher m = URL.matcher(log.toString());
      assertTrue(m.find(), log.toString());
      SimRobot robot = sim.sim().sim();
      String name = robot.getName();

      chrome.navigate(m.group(1));
      chrome.waitFor(
          "window.jaria && jaria.world.frames > 3 && jaria.world.map && jaria.selected", 30);
      assertEquals(name, chrome.eval("jaria.selected"));
      assertEquals(List.of("drive", "goal", "sim"), chrome.eval("jaria.control"));

      // The arrow key drives it forward; letting go stops it.
      ArPose start = robot.getTruePose();
      chrome.eval("document.getElementById('view').focus()");
      chrome.key("ArrowUp", 38, true);
      waitUntil(() -> robot.getTruePose().findDistanceTo(start) > 300, "the robot drove forward");
      chrome.key("ArrowUp", 38, false);
      waitUntil(() -> Math.abs(robot.getVel()) < 1, "the robot stopped when the key was let go");
      ArPose after = robot.getTruePose();
      assertTrue(after.x() > start.x() + 250, "forward is +x at home: " + start + " -> " + after);

      // Paused, the drawn robot is exactly where the simulator has it.
      clickButton(chrome, "run");
      waitUntil(() -> !sim.world().isRealTime(), "the page's Pause button paused the world");
      chrome.waitFor("jaria.world.clock && jaria.world.clock.paused", 10);
      ArPose truth = robot.getTruePose();
      chrome.waitFor(
          "Math.abs(jaria.world.robots.get('"
              + name
              + "').truePose.x - "
              + truth.x()
              + ") < 1"
              + " && Math.abs(jaria.world.robots.get('"
              + name
              + "').truePose.y - "
              + truth.y()
              + ") < 1",
          10);
      Map<?, ?> drawn = (Map<?, ?>) chrome.eval("jaria.screenOf('" + name + "')");
      Map<?, ?> expected =
          (Map<?, ?>) chrome.eval("jaria.pageOf(" + truth.x() + ", " + truth.y() + ")");
      assertEquals(num(expected.get("x")), num(drawn.get("x")), 0.5);
      assertEquals(num(expected.get("y")), num(drawn.get("y")), 0.5);
      BufferedImage shot = ImageIO.read(new ByteArrayInputStream(chrome.screenshot()));
      assertTrue(
          reddish(shot, (int) num(drawn.get("x")), (int) num(drawn.get("y")), 8),
          "the robot is drawn (red) where the simulator has it");
      assertTrue(wallNear(chrome, shot), "walls are drawn");
      clickButton(chrome, "run");
      waitUntil(sim.world()::isRealTime, "Run set it going again");

      // A click on the map sends a goal; the robot plans a path and gets there.
      ArPose goal = new ArPose(after.x() + 5000, after.y());
      chrome.eval("document.getElementById('follow').checked = false");
      Map<?, ?> at = (Map<?, ?>) chrome.eval("jaria.pageOf(" + goal.x() + ", " + goal.y() + ")");
      chrome.click(num(at.get("x")), num(at.get("y")));
      waitUntil(() -> sim.nav().getPathPlanningTask().isActive(), "the goal was taken");
      chrome.waitFor("jaria.world.robots.get('" + name + "').path.length > 1", 20);
      // The README's picture: following the robot, a little closer.
      chrome.eval("document.getElementById('follow').checked = true; jaria.view.scale *= 1.5");
      waitUntil(() -> robot.getTruePose().findDistanceTo(after) > 800, "under way");
      byte[] readme = chrome.screenshot();
      Path out = Path.of("target", "web-view.png");
      Files.write(out, readme);
      waitUntil(
          () -> robot.getTruePose().findDistanceTo(goal) < 500,
          "the robot reached the clicked goal " + goal + " (it is at " + robot.getTruePose() + ")");
      assertEquals(List.of(), chrome.errors(), "no console errors, exceptions or failed loads");
      assertFalse(log.toString().contains("Exception"), log.toString());
    } finally {
      cmd.requestStop();
      server.join(TimeUnit.SECONDS.toMillis(30));
    }
    assertFalse(server.isAlive(), "jaria web stopped");
    assertNotNull(ImageIO.read(Path.of("target", "web-view.png").toFile()));
  }

  private static double num(Object o) {
    return ((Number) o).doubleValue();
  }

  private static void clickButton(Chromium chrome, String id) throws Exception {
    Map<?, ?> r =
        (Map<?, ?>)
            chrome.eval(
                "(() => { const b = document.getElementById('"
                    + id
                    + "').getBoundingClientRect();"
                    + " return {x: b.left + b.width / 2, y: b.top + b.height / 2}; })()");
    chrome.click(num(r.get("x")), num(r.get("y")));
  }

  /** Whether a robot-red pixel lies within {@code radius} of (x, y). */
  private static boolean reddish(BufferedImage img, int x, int y, int radius) {
    for (int dx = -radius; dx <= radius; dx++) {
      for (int dy = -radius; dy <= radius; dy++) {
        int px = x + dx;
        int py = y + dy;
        if (px >= 0 && py >= 0 && px < img.getWidth() && py < img.getHeight()) {
          int rgb = img.getRGB(px, py);
          int r = (rgb >> 16) & 0xFF;
          int g = (rgb >> 8) & 0xFF;
          int b = rgb & 0xFF;
          if (r > 150 && g < 110 && b < 100) {
            return true;
          }
        }
      }
    }
    return false;
  }

  /** Whether some wall segment on screen has dark (wall-coloured) pixels at its middle. */
  private static boolean wallNear(Chromium chrome, BufferedImage img) throws Exception {
    List<?> mids =
        (List<?>)
            chrome.eval(
                "(() => { const w = jaria.world.map.walls, out = [];"
                    + " for (let i = 0; i + 3 < w.length; i += 4) {"
                    + " const p = jaria.pageOf((w[i] + w[i + 2]) / 2, (w[i + 1] + w[i + 3]) / 2);"
                    + " if (p.x > 5 && p.y > 45 && p.x < 1100 && p.y < 850) out.push([p.x, p.y]); }"
                    + " return out; })()");
    int dark = 0;
    for (Object o : mids) {
      List<?> p = (List<?>) o;
      int x = (int) Math.round(num(p.get(0)));
      int y = (int) Math.round(num(p.get(1)));
      search:
      for (int dx = -2; dx <= 2; dx++) {
        for (int dy = -2; dy <= 2; dy++) {
          int rgb = img.getRGB(x + dx, y + dy);
          if (((rgb >> 16) & 0xFF) < 90 && ((rgb >> 8) & 0xFF) < 90 && (rgb & 0xFF) < 100) {
            dark++;
            break search;
          }
        }
      }
    }
    return !mids.isEmpty() && dark >= mids.size() / 2;
  }

  /** Waits for the simulated world (it runs on its own thread at four times real time). */
  private static void waitUntil(java.util.function.BooleanSupplier done, String what)
      throws InterruptedException {
    long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(90);
    while (!done.getAsBoolean()) {
      if (System.nanoTime() > deadline) {
        throw new AssertionError("never happened: " + what);
      }
      TimeUnit.MILLISECONDS.sleep(50);
    }
  }
}
