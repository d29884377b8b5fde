package dock;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.jaria.classroom.grading.Assignment;
import org.jaria.classroom.grading.Check;
import org.jaria.classroom.grading.FirstStep;
import org.jaria.classroom.grading.Grade;
import org.jaria.classroom.grading.Grading;
import org.jaria.classroom.grading.PoseTrace;
import org.jaria.classroom.grading.Programs;
import org.jaria.classroom.grading.Solutions;
import org.jaria.classroom.grading.Texts;
import org.jaria.classroom.link.StudentContext;
import org.jaria.classroom.link.StudentLink;
import org.jaria.classroom.link.StudentSide;
import org.jaria.classroom.link.StudentStreams;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.robot.ArRobot;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;

/**
 * "Park in the dock": an example of a teacher's own assignment pack, written only against JAria's
 * public API. The student's {@link DockingProgram} gets the room's map and a robot at its home, and
 * must drive around the wall in the middle to the map's dock and stop there, within 50 mm, facing
 * the dock's heading.
 *
 * <p>The world is the map in this pack ({@code dock-room.map}); the checks are plain functions over
 * the robot's recorded true path ({@link DockChecks}); the sentences are this pack's catalogue
 * ({@code dock_en.properties}, {@code dock_es.properties}) on top of the kit's.
 */
public final class DockAssignment implements Assignment {

  /** How long the program may take, robot time. */
  static final Duration MAX_TIME = Duration.ofMinutes(2);

  @Override
  public String id() {
    return "dock";
  }

  @Override
  public String title() {
    return "Park in the dock";
  }

  @Override
  public Class<?> solutionType() {
    return DockingProgram.class;
  }

  @Override
  public String solutionClassName() {
    return "Parker";
  }

  @Override
  public String solutionShape() {
    return "a public class that implements dock.DockingProgram, with a public constructor taking"
        + " no arguments (e.g. 'public class Parker implements DockingProgram')";
  }

  @Override
  public int points() {
    return 10;
  }

  @Override
  public Texts texts(String lang) {
    return Texts.of(lang).with(DockAssignment.class, "dock");
  }

  @Override
  public List<String> checkNames(Texts t) {
    return DockChecks.names(t);
  }

  /** The room, from this pack. */
  static ArMap map() {
    try (InputStream in = DockAssignment.class.getResourceAsStream("dock-room.map")) {
      if (in == null) {
        throw new IllegalStateException("dock-room.map is missing from the dock pack");
      }
      return ArMap.read(new InputStreamReader(in, StandardCharsets.UTF_8), "dock-room.map");
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    } catch (MapFormatException e) {
      throw new IllegalStateException("dock-room.map is not a map: " + e.getMessage(), e);
    }
  }

  /** Where to park: the map's dock. */
  static ArPose dock(ArMap map) {
    return map.findFirstMapObjectOfType("Dock").orElseThrow().pose();
  }

  @Override
  public StudentSide studentSide() {
    return new StudentSide() {
      @Override
      public void setUp(StudentContext ctx) throws Solutions.SolutionException {
        DockingProgram program =
            Solutions.instantiate(
                ctx.solution(), DockingProgram.class, new Class<?>[0], new Object[0]);
        ArMap map = map();
        ArRobot robot = ctx.robot();
        // the robot starts at the map's home: its pose is given in the map's coordinates
        robot.moveTo(map.findHomePose().orElseThrow());
        ctx.setProgram(r -> program.run(r, map));
      }
    };
  }

  @Override
  public Grade grade(StudentStreams student, Texts t) {
    ArMap map = map();
    try (SimWorld world = SimWorld.create(map, SimOptions.builder().seed(7).build())) {
      SimRobot r = world.addRobot("p3dx-sh");
      try (StudentLink sim = StudentLink.connect(world, r, student, Map.of());
          PoseTrace trace = new PoseTrace(world, r)) {
        Optional<String> failed = sim.setUp();
        if (failed.isPresent()) {
          return Grading.setUpFailure(this, failed.get(), t);
        }
        Programs.Ending end = Programs.run(sim, MAX_TIME, 1, t);
        sim.runMillis(2000); // a program that returns while moving keeps moving
        List<Check> checks = new ArrayList<>();
        checks.add(end.check());
        List<Check> parking = DockChecks.parking(trace, dock(map), r.getVel(), r.getRotVel(), t);
        for (Check c : parking) {
          checks.add(end.judged(c, t));
        }
        checks.add(DockChecks.collisions(trace, t));
        return new Grade(
            id(), FirstStep.gate(checks, parking.get(0).passed(), t.get("dock.step"), t));
      }
    }
  }
}
