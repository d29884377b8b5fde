package org.jaria.sim.junit;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.lang.reflect.AnnotatedElement;
import java.util.Optional;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.robot.ArRobot;
import org.jaria.sim.OdometryError;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.BeforeEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.junit.jupiter.api.extension.ParameterContext;
import org.junit.jupiter.api.extension.ParameterResolutionException;
import org.junit.jupiter.api.extension.ParameterResolver;

/** The JUnit 5 extension behind {@link SimulatedRobotTest}. */
public final class SimulatedRobotExtension
    implements BeforeEachCallback, AfterEachCallback, ParameterResolver {

  private static final ExtensionContext.Namespace NS =
      ExtensionContext.Namespace.create(SimulatedRobotExtension.class);

  @Override
  public void beforeEach(ExtensionContext context) {
    SimulatedRobotTest config =
        find(context.getTestMethod().orElse(null))
            .or(() -> find(context.getTestClass().orElse(null)))
            .orElseThrow(
                () ->
                    new IllegalStateException(
                        "SimulatedRobotExtension needs a @SimulatedRobotTest annotation"));
    context.getStore(NS).put(SimulatedRobot.class, start(config));
  }

  private static Optional<SimulatedRobotTest> find(AnnotatedElement e) {
    return e == null
        ? Optional.empty()
        : Optional.ofNullable(e.getAnnotation(SimulatedRobotTest.class));
  }

  /** Starts the world and the robot a {@code @SimulatedRobotTest} describes. */
  static SimulatedRobot start(SimulatedRobotTest config) {
    SimOptions.Builder options = SimOptions.builder().seed(config.seed());
    if (config.odometryError()) {
      options.odometryError(OdometryError.random(0.02, 0.02));
    }
    SimWorld world = SimWorld.create(loadMap(config.map()), options.build());
    SimRobot r = world.addRobot(config.robot());
    try {
      return SimulatedRobot.connect(world, r, new ArRobot(r.getName(), world.getClock(), true));
    } catch (RuntimeException e) {
      world.close();
      throw e;
    }
  }

  private static ArMap loadMap(String map) {
    try {
      return ArMap.load(map);
    } catch (IOException e) {
      throw new UncheckedIOException(
          "cannot read the map '" + map + "' of @SimulatedRobotTest: " + e.getMessage(), e);
    } catch (MapFormatException e) {
      throw new IllegalArgumentException(
          "the map of @SimulatedRobotTest is not a valid .map file: " + e.getMessage(), e);
    }
  }

  @Override
  public void afterEach(ExtensionContext context) {
    SimulatedRobot s = context.getStore(NS).remove(SimulatedRobot.class, SimulatedRobot.class);
    if (s != null) {
      s.close();
      s.world().close();
    }
  }

  @Override
  public boolean supportsParameter(ParameterContext p, ExtensionContext e) {
    Class<?> t = p.getParameter().getType();
    return t == ArRobot.class
        || t == SimulatedRobot.class
        || t == SimWorld.class
        || t == SimRobot.class;
  }

  @Override
  public Object resolveParameter(ParameterContext p, ExtensionContext e) {
    SimulatedRobot s = e.getStore(NS).get(SimulatedRobot.class, SimulatedRobot.class);
    if (s == null) {
      throw new ParameterResolutionException("no simulated robot for this test");
    }
    Class<?> t = p.getParameter().getType();
    if (t == ArRobot.class) {
      return s.robot();
    }
    if (t == SimWorld.class) {
      return s.world();
    }
    if (t == SimRobot.class) {
      return s.sim();
    }
    return s;
  }
}
