package org.jaria.net;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import java.nio.file.Path;
import org.jaria.net.guiserver.GuiServer;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * ArNetworking's packages depend on each other without loops (read from the compiled classes; every
 * sub-package of org.jaria.net is its own node). The server ({@code server}) is at the bottom of
 * the server side, its handlers ({@code server.info}) and modes ({@code server.modes}) use it, and
 * the guiServer that assembles them ({@code guiserver}) sits on top: nothing below names it.
 */
class PackageCyclesTest {

  private static JavaClasses net;

  @BeforeAll
  static void importNet() throws Exception {
    Path classes =
        Path.of(GuiServer.class.getProtectionDomain().getCodeSource().getLocation().toURI());
    net = new ClassFileImporter().importPath(classes);
    assertTrue(net.size() > 100, "aria-net's classes were found: " + net.size());
  }

  @Test
  void packagesHaveNoCycles() {
    slices().matching("org.jaria.(**)").should().beFreeOfCycles().check(net);
  }

  @Test
  void theServerItsHandlersAndModesDoNotNameTheGuiServer() {
    noClasses()
        .that()
        .resideInAnyPackage("org.jaria.net.server..", "org.jaria.net.client..")
        .should()
        .dependOnClassesThat()
        .resideInAPackage("org.jaria.net.guiserver..")
        .check(net);
  }

  @Test
  void theServerDoesNotNameItsHandlersOrModes() {
    noClasses()
        .that()
        .resideInAPackage("org.jaria.net.server")
        .should()
        .dependOnClassesThat()
        .resideInAnyPackage("org.jaria.net.server.info", "org.jaria.net.server.modes")
        .check(net);
  }
}
