package org.jaria.tools;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import java.nio.file.Path;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The command line's packages depend on each other without loops (read from the compiled classes;
 * every sub-package of org.jaria.tools is its own node): {@code cli} (jaria and its list of
 * commands) on top, each command's package below it, the shared option types ({@code options}), the
 * desktop apps' stand-ins ({@code desktop}) and the version at the bottom. And no class here names
 * JavaFX or OpenCV: those are the apps module's, so the command line builds and starts without
 * them.
 */
class PackageCyclesTest {

  private static JavaClasses tools;

  @BeforeAll
  static void importTools() throws Exception {
    Path classes =
        Path.of(JariaCli.class.getProtectionDomain().getCodeSource().getLocation().toURI());
    tools = new ClassFileImporter().importPath(classes);
    assertTrue(tools.size() > 60, "tools' classes were found: " + tools.size());
  }

  @Test
  void packagesHaveNoCycles() {
    slices().matching("org.jaria.(**)").should().beFreeOfCycles().check(tools);
  }

  @Test
  void theCommandLineNamesNeitherJavaFxNorOpenCv() {
    noClasses()
        .should()
        .dependOnClassesThat()
        .resideInAnyPackage("javafx..", "org.opencv..", "nu.pattern..", "org.testfx..")
        .check(tools);
  }
}
