package org.jaria.sim;

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
import org.jaria.sim.camera.SimCamera;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The simulator's packages depend on each other without loops, read from the compiled classes
 * (org.jaria.sim and each of its sub-packages is one node).
 *
 * <p>One seam is allowed: the robot model ({@code org.jaria.sim.robot}) and the ARCOS server
 * ({@code org.jaria.sim.server}, whose SIMSTAT reports the odometry error) name the option records
 * {@link OdometryError} and {@link SonarOptions}. A user passes them to {@code SimOptions}, so they
 * live beside it in {@code org.jaria.sim}, while {@code org.jaria.sim} builds robots and servers
 * out of those two packages. Moving the records would rename public API that tools, classroom and
 * tests import by name. So {@code robot} and {@code server} may name those two and nothing else of
 * {@code org.jaria.sim}; every other dependency between packages goes one way. The camera reads the
 * world through its own interfaces ({@code CameraScene}, {@code CameraMount}), so the world holding
 * the camera's coloured objects makes no loop. See docs/arrobot-and-the-cycle.md, "Module and
 * package rules".
 */
class PackageCyclesTest {

  /** What {@code org.jaria.sim.robot} and {@code .server} may use of {@code org.jaria.sim}. */
  static final List<Class<?>> SEAM = List.of(OdometryError.class, SonarOptions.class);

  private static JavaClasses sim;

  @BeforeAll
  static void importSimulator() throws URISyntaxException {
    // the simulator's own classes folder (or jar): not its tests, not other modules
    Path classes =
        Path.of(SimWorld.class.getProtectionDomain().getCodeSource().getLocation().toURI());
    sim = new ClassFileImporter().importPath(classes);
    assertTrue(
        sim.contain(SimWorld.class) && sim.contain(SimCamera.class) && sim.size() > 70,
        "the simulator's classes were found: " + sim.size());
  }

  /** The seam's classes and their nested classes (OdometryError.Mode). */
  private static DescribedPredicate<JavaClass> seam() {
    return describe(
        "the option records " + SEAM.stream().map(Class::getSimpleName).toList(),
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
      rule =
          rule.ignoreDependency(
              resideInAnyPackage("org.jaria.sim.robot", "org.jaria.sim.server"), seam());
    }
    return rule.evaluate(sim);
  }

  private static String details(EvaluationResult r) {
    return String.join("\n", r.getFailureReport().getDetails());
  }

  @Test
  void thePackagesFormNoLoopBesidesTheSeam() {
    EvaluationResult r = cycles(true);
    assertFalse(r.hasViolation(), () -> details(r));
  }

  @Test
  void robotAndServerUseNothingOfTheRootPackageButTheSeam() {
    EvaluationResult r =
        noClasses()
            .that()
            .resideInAnyPackage("org.jaria.sim.robot", "org.jaria.sim.server")
            .should()
            .dependOnClassesThat(resideInAPackage("org.jaria.sim").and(not(seam())))
            .evaluate(sim);
    assertFalse(r.hasViolation(), () -> details(r));
  }

  @Test
  void theCameraDoesNotNameTheWorld() {
    // The circle issue 17 named: SimWorld holds ColoredObjects, so camera must not look back.
    EvaluationResult r =
        noClasses()
            .that()
            .resideInAPackage("org.jaria.sim.camera")
            .should()
            .dependOnClassesThat()
            .resideInAPackage("org.jaria.sim")
            .evaluate(sim);
    assertFalse(r.hasViolation(), () -> details(r));
  }

  @Test
  void theSeamIsStillNeededAndTheCheckSeesLoops() {
    // Without the seam the sim <-> robot and sim <-> server loops show: the checker sees cycles,
    // and the day this
    // fails the seam above can go.
    EvaluationResult r = cycles(false);
    assertTrue(r.hasViolation(), "expected the sim <-> sim.robot loop through the option records");
    String report = details(r);
    assertTrue(report.contains("OdometryError") || report.contains("SonarOptions"), report);
  }
}
