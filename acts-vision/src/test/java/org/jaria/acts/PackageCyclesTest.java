package org.jaria.acts;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * ACTS's packages depend on each other without loops (read from the compiled classes; every
 * sub-package of org.jaria.acts is its own node). The root package is ARIA's client side
 * (ArACTS_1_2, its blobs and the wire protocol's numbers) and names no part of the tracker; images,
 * colour channels and blobs build on it and on each other one way; the server and the actions are
 * on top.
 */
class PackageCyclesTest {

  private static JavaClasses acts;

  @BeforeAll
  static void importActs() throws Exception {
    Path classes =
        Path.of(ArACTS_1_2.class.getProtectionDomain().getCodeSource().getLocation().toURI());
    acts = new ClassFileImporter().importPath(classes);
    assertTrue(acts.size() > 30, "acts-vision's classes were found: " + acts.size());
  }

  @Test
  void packagesHaveNoCycles() {
    slices().matching("org.jaria.(**)").should().beFreeOfCycles().check(acts);
  }

  @Test
  void theClientSideNamesNoPartOfTheTracker() {
    noClasses()
        .that()
        .resideInAPackage("org.jaria.acts")
        .should()
        .dependOnClassesThat()
        .resideInAnyPackage(
            "org.jaria.acts.blob..",
            "org.jaria.acts.color..",
            "org.jaria.acts.image..",
            "org.jaria.acts.server..")
        .check(acts);
  }
}
