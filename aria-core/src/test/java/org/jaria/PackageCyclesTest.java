package org.jaria;

import static com.tngtech.archunit.base.DescribedPredicate.describe;
import static com.tngtech.archunit.base.DescribedPredicate.not;
import static com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAPackage;
import static com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAnyPackage;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.base.DescribedPredicate;
import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.lang.EvaluationResult;
import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.List;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.action.ArPriorityResolver;
import org.jaria.action.ArResolver;
import org.jaria.range.ArRangeDevice;
import org.jaria.range.ArSensorReading;
import org.jaria.robot.ArRobot;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * aria-core's packages depend on each other without loops, read from the compiled classes (every
 * package is its own node, sub-packages included: {@code protocol.packets} is not {@code
 * protocol}).
 *
 * <p>One seam is allowed, and it is ARIA's own: {@code ArRobot} takes actions, a resolver and range
 * devices ({@code addAction(ArAction, int)}, {@code setResolver(ArResolver)}, {@code
 * addRangeDevice(ArRangeDevice)}, {@code getSonarReading} giving an {@code ArSensorReading}), and
 * those are handed the robot back ({@code ArAction.getRobot()}, {@code ArRangeDevice.setRobot}). So
 * {@code robot} may name the plug-in contracts listed in {@link #SEAM}, and nothing else of {@code
 * action} or {@code range}; every other dependency between packages goes one way. See
 * docs/arrobot-and-the-cycle.md, "Module and package rules".
 */
class PackageCyclesTest {

  /** What {@code org.jaria.robot} may use of {@code action} and {@code range}: ARIA's seam. */
  static final List<Class<?>> SEAM =
      List.of(
          ArAction.class,
          ArActionDesired.class,
          ArResolver.class,
          ArPriorityResolver.class,
          ArRangeDevice.class,
          ArSensorReading.class);

  private static JavaClasses core;

  @BeforeAll
  static void importAriaCore() throws URISyntaxException {
    // aria-core's own classes folder (or jar): not its tests, not other modules on the class path
    Path classes =
        Path.of(ArRobot.class.getProtectionDomain().getCodeSource().getLocation().toURI());
    core = new ClassFileImporter().importPath(classes);
    assertTrue(
        core.contain(ArAction.class) && core.size() > 150,
        "aria-core's classes were found: " + core.size());
  }

  /** The seam's classes and their nested classes (ArResolver.PrioritizedAction, ...). */
  private static DescribedPredicate<JavaClass> seam() {
    return describe(
        "ARIA's seam " + SEAM.stream().map(Class::getSimpleName).toList(),
        c ->
            SEAM.stream()
                .anyMatch(
                    s ->
                        c.getName().equals(s.getName())
                            || c.getName().startsWith(s.getName() + "$")));
  }

  private static EvaluationResult cycles(boolean allowSeam) {
    var rule = slices().matching("org.jaria.(**)").should().beFreeOfCycles();
    if (allowSeam) {
      rule = rule.ignoreDependency(resideInAPackage("org.jaria.robot"), seam());
    }
    return rule.evaluate(core);
  }

  @Test
  void thePackagesFormNoLoopBesidesAriasSeam() {
    EvaluationResult r = cycles(true);
    assertFalse(r.hasViolation(), () -> String.join("\n", r.getFailureReport().getDetails()));
  }

  @Test
  void theRobotUsesNothingOfActionAndRangeButTheSeam() {
    EvaluationResult r =
        noClasses()
            .that()
            .resideInAPackage("org.jaria.robot")
            .should()
            .dependOnClassesThat(
                resideInAnyPackage("org.jaria.action", "org.jaria.range").and(not(seam())))
            .evaluate(core);
    assertFalse(r.hasViolation(), () -> String.join("\n", r.getFailureReport().getDetails()));
  }

  @Test
  void theProtocolNamesNoneOfItsPackets() {
    // The packets (protocol.packets) are built on the protocol's ArRobotPacket; the describer of
    // packets (PacketFormatter) lives with them, so the protocol does not look back.
    EvaluationResult r =
        noClasses()
            .that()
            .resideInAPackage("org.jaria.protocol")
            .should()
            .dependOnClassesThat()
            .resideInAPackage("org.jaria.protocol.packets")
            .evaluate(core);
    assertFalse(r.hasViolation(), () -> String.join("\n", r.getFailureReport().getDetails()));
  }

  @Test
  void theSeamIsStillNeededAndTheCheckSeesLoops() {
    // Without the seam the robot <-> action and robot <-> range loops show: the checker sees
    // cycles, and the day this fails the seam above can go.
    EvaluationResult r = cycles(false);
    assertTrue(r.hasViolation(), "expected the robot <-> action loop of ARIA's API");
    String report = String.join("\n", r.getFailureReport().getDetails());
    assertTrue(report.contains("robot") && report.contains("action"), report);
  }
}
