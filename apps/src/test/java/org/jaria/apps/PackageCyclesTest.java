package org.jaria.apps;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The desktop apps' packages depend on each other without loops (read from the compiled classes;
 * every sub-package of org.jaria.apps is its own node): the shared JavaFX pieces ({@code fx}) at
 * the bottom, each app on them, {@code jaria screenshot} above the apps it renders, and the
 * provider the command line finds ({@code org.jaria.apps}) on top.
 */
class PackageCyclesTest {

  private static JavaClasses apps;

  @BeforeAll
  static void importApps() throws Exception {
    Path classes =
        Path.of(
            DesktopAppsProvider.class.getProtectionDomain().getCodeSource().getLocation().toURI());
    apps = new ClassFileImporter().importPath(classes);
    assertTrue(apps.size() > 80, "the apps' classes were found: " + apps.size());
  }

  @Test
  void packagesHaveNoCycles() {
    slices().matching("org.jaria.(**)").should().beFreeOfCycles().check(apps);
  }

  @Test
  void theSharedPiecesNameNoApp() {
    noClasses()
        .that()
        .resideInAPackage("org.jaria.apps.fx")
        .should()
        .dependOnClassesThat()
        .resideInAnyPackage(
            "org.jaria.apps",
            "org.jaria.apps.mapper",
            "org.jaria.apps.eztrain",
            "org.jaria.apps.monitor",
            "org.jaria.apps.simview",
            "org.jaria.apps.screenshot")
        .check(apps);
  }
}
