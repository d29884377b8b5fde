package org.jaria.simguiserver;

import java.io.IOException;
import java.util.Locale;
import java.util.Objects;
import org.jaria.map.ArMap;
import org.jaria.net.arnl.ArnlNavigation;
import org.jaria.net.guiserver.GuiServer;
import org.jaria.net.server.MapFolder;
import org.jaria.net.server.ServerOptions;
import org.jaria.ptz.ArVCC4;
import org.jaria.robot.ArRobot;
import org.jaria.sim.OdometryError;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.camera.SimCamera;
import org.jaria.sim.client.SimulatedRobot;

/**
 * The thesis's guiServer on an embedded simulator: a world on a map with one robot (odometry that
 * drifts, as a real robot's does), SonARNL localization and path planning, the simulated camera as
 * video with the robot's VC-C4 pointing it, and a {@link GuiServer} serving all of it. For {@code
 * jaria demo guiserver} without a robot, the monitor's tests and the network benchmark.
 *
 * <p>With a speed-up above zero the world runs on its own thread at that multiple of real time;
 * with zero it runs in lockstep, only when the caller advances it ({@link #sim()}).
 */
public final class SimulatedGuiServer implements AutoCloseable {

  /**
   * What to run.
   *
   * @param map the map of the world and of the robot
   * @param mapName its name for clients (the file name)
   * @param model the robot model ("p3dx-sh")
   * @param seed seed of the simulator and the localization
   * @param server port, login and limits
   * @param mode where localization and planning run (threaded for real time, synchronous for
   *     lockstep)
   * @param speedUp simulated seconds per real second; 0: lockstep, advanced by the caller
   * @param camera whether to serve the simulated camera as video, and its VC-C4 for clients to
   *     point
   */
  public record Options(
      ArMap map,
      String mapName,
      String model,
      long seed,
      ServerOptions server,
      ArnlNavigation.Mode mode,
      double speedUp,
      boolean camera) {

    /** Checks the values. */
    public Options {
      Objects.requireNonNull(map, "map");
      Objects.requireNonNull(server, "server options");
      Objects.requireNonNull(mode, "mode");
      if (!(speedUp >= 0)) {
        throw new IllegalArgumentException("speed-up must be 0 (lockstep) or positive");
      }
    }

    /** A p3dx-sh in real time with threaded localization and planning, camera on. */
    public static Options realTime(ArMap map, String mapName, ServerOptions server) {
      return new Options(
          map, mapName, "p3dx-sh", 1, server, ArnlNavigation.Mode.THREADED, 1.0, true);
    }
  }

  private final SimWorld world;
  private final SimulatedRobot sim;
  private final ArnlNavigation nav;
  private final SimCameraVideo video;
  private final GuiServer gui;
  private final boolean localized;

  private SimulatedGuiServer(
      SimWorld world,
      SimulatedRobot sim,
      ArnlNavigation nav,
      SimCameraVideo video,
      GuiServer gui,
      boolean localized) {
    this.world = world;
    this.sim = sim;
    this.nav = nav;
    this.video = video;
    this.gui = gui;
    this.localized = localized;
  }

  /**
   * Builds the world, connects the robot, localizes it at the map's home and opens the server.
   *
   * @throws IOException if the server's port cannot be opened
   */
  public static SimulatedGuiServer start(Options o) throws IOException {
    return start(o, new MapFolder(null));
  }

  /**
   * As {@link #start(Options)}, letting clients switch the server to a map of {@code maps} (ARIA's
   * {@code Files/Map} parameter; the simulated world keeps its own map, as a real building would).
   */
  public static SimulatedGuiServer start(Options o, MapFolder maps) throws IOException {
    SimWorld world =
        SimWorld.create(
            o.map(),
            SimOptions.builder()
                .seed(o.seed())
                .odometryError(OdometryError.random(0.02, 0.02))
                .build());
    SimulatedRobot sim = null;
    ArnlNavigation nav = null;
    SimCameraVideo video = null;
    try {
      SimRobot r = world.addRobot(o.model());
      sim = SimulatedRobot.connect(world, r);
      ArRobot robot = sim.robot();
      nav = ArnlNavigation.create(robot, o.map(), o.mode(), o.seed());
      robot.enableMotors();
      sim.runMillis(1500);
      boolean localized = nav.localizeAtHome();
      ArVCC4 ptz = null;
      if (o.camera()) {
        // The simulated robot's VC-C4 on AUX1, which its camera follows: clients that pan and
        // tilt it (ptzCameraClientExample, the monitor) see the picture turn.
        SimCamera cam = SimCamera.onTop(world, r);
        cam.setFollowAuxPtz(true);
        video = new SimCameraVideo(cam, "Simulated camera", 5);
        ptz = new ArVCC4(robot);
        ptz.init();
      }
      GuiServer gui =
          GuiServer.builder(robot)
              .options(o.server())
              .map(o.map(), o.mapName())
              .localization(nav.localization())
              .pathPlanning(nav.pathPlanning())
              .config(nav.configRegistry())
              .video(video)
              .ptz(ptz)
              .mapChange(maps, nav::setMap)
              .build();
      nav.addCommands(gui.getCommands());
      gui.open();
      if (o.speedUp() > 0) {
        world.startRealTime(o.speedUp());
      }
      return new SimulatedGuiServer(world, sim, nav, video, gui, localized);
    } catch (IOException | RuntimeException e) {
      if (video != null) {
        video.close();
      }
      if (nav != null) {
        nav.close();
      }
      if (sim != null) {
        sim.close();
      }
      world.close();
      throw e;
    }
  }

  /** The world. */
  public SimWorld world() {
    return world;
  }

  /** The robot's connection in lockstep (advance it when the speed-up is 0). */
  public SimulatedRobot sim() {
    return sim;
  }

  /** The robot. */
  public ArRobot robot() {
    return sim.robot();
  }

  /** Localization and path planning. */
  public ArnlNavigation nav() {
    return nav;
  }

  /** The server. */
  public GuiServer gui() {
    return gui;
  }

  /** The port the server listens on. */
  public int port() {
    return gui.getServer().getPort();
  }

  /** Whether localizing at home at start-up passed. */
  public boolean wasLocalized() {
    return localized;
  }

  @Override
  public String toString() {
    return String.format(
        Locale.ROOT,
        "SimulatedGuiServer[%s on port %d, %s]",
        sim.sim().getName(),
        port(),
        world.isRealTime() ? "real time" : "lockstep");
  }

  /** Stops the server, the camera, the world and the robot's tasks. */
  @Override
  public void close() {
    gui.close();
    if (video != null) {
      video.close();
    }
    world.stopRealTime();
    nav.close();
    sim.close();
    world.close();
  }
}
