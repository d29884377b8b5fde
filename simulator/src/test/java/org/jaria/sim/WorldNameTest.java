package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Worlds have names of their own, and their real-time threads are named after them. */
class WorldNameTest {

  private static Set<String> threadNames() {
    return Thread.getAllStackTraces().keySet().stream()
        .filter(Thread::isAlive)
        .map(Thread::getName)
        .collect(Collectors.toSet());
  }

  @Test
  void twoWorldsOnTheSameMapRunOnDifferentlyNamedThreads() {
    try (SimWorld a = SimWorld.bundled("office", SimOptions.defaults());
        SimWorld b = SimWorld.bundled("office", SimOptions.defaults())) {
      assertTrue(a.getName().matches("world-\\d+-office"), a.getName());
      assertNotEquals(a.getName(), b.getName());
      a.startRealTime(0);
      b.startRealTime(0);
      Set<String> running = threadNames();
      assertTrue(running.contains("jaria-sim-" + a.getName()), running.toString());
      assertTrue(running.contains("jaria-sim-" + b.getName()), running.toString());
      a.stopRealTime();
      assertFalse(threadNames().contains("jaria-sim-" + a.getName()), "stopped and joined");
      assertTrue(threadNames().contains("jaria-sim-" + b.getName()), "the other runs on");
    }
  }

  @Test
  void aWorldLoadedFromAFileIsNamedAfterIt(@TempDir Path dir) throws IOException {
    Path map = dir.resolve("lab.map");
    Files.writeString(map, "2D-Map\nLINES\n0 0 1000 0\nDATA\n");
    try (SimWorld w = SimWorld.load(map, SimOptions.defaults())) {
      assertTrue(w.getName().endsWith("-lab"), w.getName());
    }
  }
}
