package org.jaria.tools.demo;

import java.io.IOException;
import java.io.UncheckedIOException;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;

/**
 * A simulator started inside a demo: a world on a bundled map or a map file, one robot, a real TCP
 * server on a free port, running in real time. The demo's program connects to it exactly as it
 * would to MobileSim or to {@code ./jaria sim}.
 */
final class EmbeddedSimulator implements AutoCloseable {

  final SimWorld world;
  final SimRobot robot;

  EmbeddedSimulator(String map, String model, long seed) throws IOException {
    this(map, RobotOptions.of(model), seed);
  }

  EmbeddedSimulator(String map, RobotOptions robotOptions, long seed) throws IOException {
    world = SimWorld.create(loadMap(map), SimOptions.builder().seed(seed).basePort(0).build());
    robot = world.addRobot(robotOptions);
    world.listen();
    world.startRealTime(1.0);
  }

  /** The robot's TCP port. */
  int port() {
    return robot.getPort();
  }

  /** Arguments that point an ARIA-style program at this simulator. */
  String[] connectArgs() {
    return new String[] {"-rh", "127.0.0.1", "-rrtp", String.valueOf(port())};
  }

  static ArMap loadMap(String map) {
    try {
      return ArMap.load(map);
    } catch (IOException e) {
      throw new UncheckedIOException(e.getMessage(), e); // says what is wrong and what to do
    } catch (MapFormatException e) {
      throw new IllegalArgumentException(e.getMessage(), e);
    }
  }

  @Override
  public void close() {
    world.close();
  }
}
