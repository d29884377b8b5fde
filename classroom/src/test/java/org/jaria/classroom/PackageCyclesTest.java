package org.jaria.classroom;

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
import org.jaria.classroom.classgrading.ClassGrading;
import org.jaria.classroom.grading.Programs;
import org.jaria.classroom.grading.Solutions;
import org.jaria.classroom.link.StudentContext;
import org.jaria.classroom.link.StudentSide;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The classroom kit's packages depend on each other without loops, read from the compiled classes
 * (org.jaria.classroom and each of its sub-packages is one node). From the bottom: the sandbox, the
 * robot link ({@code link}), the assignments' API and the grader ({@code grading}), the packs and
 * the platforms on it, the built-in assignments beside them, and a teacher's whole run ({@code
 * classgrading}, which {@code jaria grade} fills in) on top.
 *
 * <p>One seam is allowed, and the assignment packs' API forces it: an {@code Assignment} (in {@code
 * grading}, the type every pack's {@code META-INF/services} file names) hands out its {@link
 * StudentSide} and grades over {@code StudentStreams} (in {@code link}), while {@code
 * StudentSide.setUp} throws {@link Solutions.SolutionException} and {@code
 * StudentContext.setProgram} takes a {@link Programs.Body} (in {@code grading}). Packs already
 * written import all of them by these names, so none can move. So {@code link} may name the two
 * types in {@link #SEAM} and nothing else of {@code grading}; every other dependency between
 * packages goes one way. See docs/arrobot-and-the-cycle.md, "Module and package rules".
 */
class PackageCyclesTest {

  /** What {@code org.jaria.classroom.link} may use of {@code grading}: the pack API's seam. */
  static final List<Class<?>> SEAM =
      List.of(Solutions.SolutionException.class, Programs.Body.class);

  /** The built-in assignments: found through META-INF/services, as a pack's are. */
  static final String[] ASSIGNMENTS = {
    "org.jaria.classroom.square",
    "org.jaria.classroom.wall",
    "org.jaria.classroom.goals",
    "org.jaria.classroom.ball"
  };

  private static JavaClasses kit;

  @BeforeAll
  static void importTheKit() throws URISyntaxException {
    // the classroom module's own classes folder (or jar): not its tests, not other modules
    Path classes =
        Path.of(RobotProgram.class.getProtectionDomain().getCodeSource().getLocation().toURI());
    kit = new ClassFileImporter().importPath(classes);
    assertTrue(
        kit.contain(ClassGrading.class) && kit.contain(StudentSide.class) && kit.size() > 60,
        "the classroom kit's classes were found: " + kit.size());
  }

  /** The seam's classes and their nested classes. */
  private static DescribedPredicate<JavaClass> seam() {
    return describe(
        "the pack API's seam " + SEAM.stream().map(Class::getName).toList(),
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
      rule = rule.ignoreDependency(resideInAPackage("org.jaria.classroom.link"), seam());
    }
    return rule.evaluate(kit);
  }

  @Test
  void thePackagesFormNoLoopBesidesThePackApisSeam() {
    EvaluationResult r = cycles(true);
    assertFalse(r.hasViolation(), () -> String.join("\n", r.getFailureReport().getDetails()));
  }

  @Test
  void theLinkUsesNothingOfGradingButTheSeam() {
    EvaluationResult r =
        noClasses()
            .that()
            .resideInAPackage("org.jaria.classroom.link")
            .should()
            .dependOnClassesThat(resideInAPackage("org.jaria.classroom.grading").and(not(seam())))
            .evaluate(kit);
    assertFalse(r.hasViolation(), () -> String.join("\n", r.getFailureReport().getDetails()));
  }

  @Test
  void onlyTheStudentsContractsNameTheSeam() {
    // StudentSide and StudentContext are what a pack's student half implements and is handed; the
    // rest of the link (frames, the grader's end, the audit) knows no assignment at all.
    EvaluationResult r =
        noClasses()
            .that()
            .resideInAPackage("org.jaria.classroom.link")
            .and(
                describe(
                    "are not StudentSide or StudentContext",
                    (JavaClass c) ->
                        !c.isEquivalentTo(StudentSide.class)
                            && !c.isEquivalentTo(StudentContext.class)))
            .should()
            .dependOnClassesThat(seam())
            .evaluate(kit);
    assertFalse(r.hasViolation(), () -> String.join("\n", r.getFailureReport().getDetails()));
  }

  @Test
  void theGraderNamesNoAssignment() {
    // The built-in assignments are found through META-INF/services, exactly as a pack's are, so
    // grading a pack takes the same path as grading the kit's own.
    EvaluationResult r =
        noClasses()
            .that(not(resideInAnyPackage(ASSIGNMENTS)))
            .should()
            .dependOnClassesThat()
            .resideInAnyPackage(ASSIGNMENTS)
            .evaluate(kit);
    assertFalse(r.hasViolation(), () -> String.join("\n", r.getFailureReport().getDetails()));
  }

  @Test
  void theSeamIsStillNeededAndTheCheckSeesLoops() {
    // Without the seam the grading <-> link loop of the pack API shows: the checker sees cycles,
    // and the day this fails the seam above can go.
    EvaluationResult r = cycles(false);
    assertTrue(r.hasViolation(), "expected the grading <-> link loop of the pack API");
    String report = String.join("\n", r.getFailureReport().getDetails());
    assertTrue(report.contains("grading") && report.contains("link"), report);
  }
}
