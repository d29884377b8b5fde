package org.jaria.web;

import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import java.nio.file.Path;
import org.jaria.web.server.WebServer;
import org.junit.jupiter.api.Test;

/**
 * The web view's packages depend on each other without loops (read from the compiled classes; every
 * sub-package of org.jaria.web is its own node): the model at the bottom, then JSON, the protocol
 * and the controls, the sources, the server, and the recording on top.
 */
@org.junit.jupiter.api.Tag("slow")
class PackageCyclesTest {

  @Test
  void packagesHaveNoCycles() throws Exception {
    Path classes =
        Path.of(WebServer.class.getProtectionDomain().getCodeSource().getLocation().toURI());
    JavaClasses web = new ClassFileImporter().importPath(classes);
    assertTrue(web.size() > 30, "the web module's classes were found: " + web.size());
    slices().matching("org.jaria.web.(**)").should().beFreeOfCycles().check(web);
  }

  @Test
  void theModelAndTheProtocolKnowNothingOfTheServer() throws Exception {
    Path classes =
        Path.of(WebServer.class.getProtectionDomain().getCodeSource().getLocation().toURI());
    JavaClasses web = new ClassFileImporter().importPath(classes);
    com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses()
        .that()
        .resideInAnyPackage("org.jaria.web.model..", "org.jaria.web.foxglove..")
        .should()
        .dependOnClassesThat()
        .resideInAnyPackage(
            "org.jaria.web.server..",
            "org.jaria.web.source..",
            "org.eclipse.jetty..",
            "org.jaria.sim..")
        .check(web);
  }
}
