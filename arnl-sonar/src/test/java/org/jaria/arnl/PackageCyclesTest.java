package org.jaria.arnl;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * SonARNL's packages depend on each other without loops (read from the compiled classes; every
 * sub-package of org.jaria.arnl is its own node): the occupancy grid at the bottom, localization
 * ({@code mcl}) and planning ({@code plan}) on it, and ARNL's tasks and actions ({@code
 * org.jaria.arnl}) on top.
 */
class PackageCyclesTest {

  private static JavaClasses arnl;

  @BeforeAll
  static void importArnl() throws Exception {
    Path classes = Path.of(Arnl.class.getProtectionDomain().getCodeSource().getLocation().toURI());
    arnl = new ClassFileImporter().importPath(classes);
    assertTrue(arnl.size() > 40, "arnl-sonar's classes were found: " + arnl.size());
  }

  @Test
  void packagesHaveNoCycles() {
    slices().matching("org.jaria.(**)").should().beFreeOfCycles().check(arnl);
  }

  @Test
  void theAlgorithmsKnowNothingOfArnlsTasks() {
    noClasses()
        .that()
        .resideInAnyPackage(
            "org.jaria.arnl.grid..", "org.jaria.arnl.mcl..", "org.jaria.arnl.plan..")
        .should()
        .dependOnClassesThat()
        .resideInAPackage("org.jaria.arnl")
        .check(arnl);
  }
}
