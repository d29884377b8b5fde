package org.jaria.tools.cli;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.jaria.action.ArActionGroupWander;
import org.jaria.clock.Clock;
import org.jaria.connection.RobotAddress;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.mapping.SonarSketch;
import org.jaria.range.ArSensorReading;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.sim.client.SimulatedRobot;
import org.jaria.tools.sim.SeededDrive;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code jaria map sketch}: a robot without a laser wanders, and what its sonar sees is sketched
 * from its odometry ({@link SonarSketch}) into a {@code .map} of points (no lines) the map editor
 * shows for tracing walls, and/or a {@code .png} picture; both say they are a sketch, not a map to
 * localize on.
 */
@Command(
    name = "sketch",
    description = {
      "Sketch a building with the sonar of a robot without a laser: the robot wanders and each"
          + " echo is drawn from its odometry. The sketch (.map points without lines, or .png) is"
          + " a background for tracing walls in the map editor, not a map for localization.",
      "Example: jaria map sketch --sim lab.map --seconds 300 -o sketch.map -o sketch.png"
    })
final class MapSketchCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(
      names = "--sim",
      paramLabel = "MAP",
      description = "Wander an embedded simulator of this map, as fast as the computer goes.")
  String sim;

  @Option(
      names = "--remote",
      paramLabel = "HOST[:PORT]|DEVICE",
      description = "Wander the robot or simulator at this address, in real time.")
  String remote;

  @Option(
      names = {"-o", "--output"},
      paramLabel = "FILE",
      required = true,
      description =
          "Write the sketch: FILE.map (points) or FILE.png (a picture); give -o twice for"
              + " both.")
  List<Path> outputs = new ArrayList<>();

  @Option(
      names = "--seconds",
      paramLabel = "S",
      description = "How long to wander (default: ${DEFAULT-VALUE}).")
  double seconds = 300;

  @Option(
      names = "--odometry-error",
      paramLabel = "SPEC",
      description = "With --sim: none, constant:T,R or random:T,R (default: ${DEFAULT-VALUE}).")
  String odometryError = "random:0.02,0.02";

  @Option(names = "--seed", description = "With --sim: random seed (default: ${DEFAULT-VALUE}).")
  long seed = 1;

  @Override
  public Integer call() throws InterruptedException {
    PrintWriter out = spec.commandLine().getOut();
    PrintWriter err = spec.commandLine().getErr();
    if ((sim == null) == (remote == null)) {
      err.println("give --sim MAP (an embedded simulator) or --remote HOST:PORT (a robot)");
      return 2;
    }
    if (!(seconds > 0) || seconds > 86_400) {
      err.println("--seconds must be positive and at most a day");
      return 2;
    }
    for (Path o : outputs) {
      String n = o.getFileName().toString().toLowerCase(Locale.ROOT);
      if (!n.endsWith(".map") && !n.endsWith(".png")) {
        err.println("-o " + o + ": a sketch is written as .map or .png");
        return 2;
      }
    }
    try {
      SonarSketch s = sim != null ? onSimulator(out) : onRobot(out, err);
      if (s == null) {
        return 1;
      }
      int cells = s.occupied().length / 2;
      for (Path o : outputs) {
        if (o.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".png")) {
          ImageIO.write(picture(s), "png", o.toFile());
        } else {
          s.writeMap(o);
        }
        out.printf(Locale.ROOT, "wrote %s%n", o);
      }
      out.printf(
          Locale.ROOT,
          "sonar sketch: %d echoes, %d occupied cells of %d mm. A sketch from odometry: trace the"
              + " walls over it in the map editor (jaria mapper); do not localize on it.%n",
          s.readings(),
          cells,
          SonarSketch.CELL_MM);
      return 0;
    } catch (IllegalArgumentException
        | IllegalStateException
        | IOException
        | MapFormatException e) {
      err.println(e.getMessage());
      return 1;
    }
  }

  private SonarSketch onSimulator(PrintWriter out) throws IOException, MapFormatException {
    SimulatedRobot s = SeededDrive.p3dx(ArMap.load(sim), seed, odometryError);
    try {
      SonarSketch sketch = start(s.robot());
      out.printf(Locale.ROOT, "sketching %s with the sonar for %.0f s (simulated)%n", sim, seconds);
      out.flush();
      s.runMillis((long) (seconds * 1000));
      s.robot().stop();
      return sketch;
    } finally {
      s.close();
      s.world().close();
    }
  }

  private SonarSketch onRobot(PrintWriter out, PrintWriter err) throws InterruptedException {
    ArRobot robot = new ArRobot();
    robot.setDeviceConnection(RobotAddress.parse(remote).connection(Clock.system()));
    if (!robot.blockingConnect()) {
      err.println("could not connect to " + remote + ": " + robot.getConnectFailure());
      return null;
    }
    try {
      robot.runAsync(true);
      SonarSketch sketch;
      robot.lock();
      try {
        sketch = start(robot);
      } finally {
        robot.unlock();
      }
      out.printf(Locale.ROOT, "sketching %s with the sonar for %.0f s%n", remote, seconds);
      out.flush();
      long end = System.nanoTime() + (long) (seconds * 1e9);
      while (System.nanoTime() < end && robot.isConnected()) {
        TimeUnit.MILLISECONDS.sleep(200); // waiting for the wander to run its course
      }
      robot.lock();
      try {
        robot.remUserTask("sonar sketch");
        robot.stop();
      } finally {
        robot.unlock();
      }
      return sketch;
    } finally {
      robot.stopRunning();
      robot.disconnect();
    }
  }

  /** Sonar, the sketch's task on the robot's cycle, and ARIA's wander. */
  private static SonarSketch start(ArRobot robot) {
    SonarSketch sketch = new SonarSketch();
    robot.addRangeDevice(new ArSonarDevice());
    robot.addUserTask(
        "sonar sketch",
        60,
        () -> {
          // On the cycle thread only; the sketch is read once the task is removed.
          for (int i = 0; i < robot.getNumSonar(); i++) {
            ArSensorReading e = robot.getSonarReading(i);
            if (e != null && e.isNew(robot.getCounter())) {
              ArPose p = e.getPoseTaken();
              sketch.add(p, e.getSensorX(), e.getSensorY(), e.getSensorTh(), e.range());
            }
          }
        });
    new ArActionGroupWander(robot).activateExclusive();
    robot.enableMotors();
    return sketch;
  }

  /** The sketch as a picture: free light, occupied dark, unknown grey, with its label. */
  static BufferedImage picture(SonarSketch s) {
    SonarSketch.Grid g = s.grid();
    int scale = 3;
    int caption = 24;
    int w = Math.max(1, g.width()) * scale;
    int h = Math.max(1, g.height()) * scale + caption;
    BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
    for (int row = 0; row < g.height(); row++) {
      for (int col = 0; col < g.width(); col++) {
        float o = g.odds(col, row);
        double p = 1 / (1 + Math.exp(-o));
        int v = (int) Math.round(255 * (1 - p));
        int rgb = v << 16 | v << 8 | v;
        int y0 = h - (row + 1) * scale; // y up, as on a map
        for (int dy = 0; dy < scale; dy++) {
          for (int dx = 0; dx < scale; dx++) {
            img.setRGB(col * scale + dx, y0 + dy, rgb);
          }
        }
      }
    }
    Graphics2D gr = img.createGraphics();
    try {
      gr.setColor(new Color(0xB00020));
      gr.fillRect(0, 0, w, caption);
      gr.setColor(Color.WHITE);
      gr.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 13));
      gr.drawString("SONAR SKETCH (odometry) - not a map for localization", 6, 17);
    } finally {
      gr.dispose();
    }
    return img;
  }
}
