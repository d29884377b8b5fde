package org.jaria.acts.image;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import org.junit.jupiter.api.Test;

/**
 * This library opens no camera itself: without a driver on the class path (acts-camera is not a
 * dependency of acts-vision), asking for one says how to get it instead of failing on a missing
 * class.
 */
class CamerasTest {

  @Test
  void withoutADriverACameraSaysWhatToAdd() {
    assertTrue(Cameras.driver().isEmpty(), "no camera driver in acts-vision's own tests");
    IOException e = assertThrows(IOException.class, () -> Cameras.open("0", 160, 120));
    assertTrue(e.getMessage().contains("org.jaria:acts-camera"), e.getMessage());
    assertTrue(e.getMessage().contains("-f FILE"), e.getMessage());
    IOException list = assertThrows(IOException.class, Cameras::parameterList);
    assertTrue(list.getMessage().contains("org.jaria:acts-camera"), list.getMessage());
  }

  @Test
  void noClassOfThisLibraryNamesOpenCv() throws Exception {
    var classes =
        new com.tngtech.archunit.core.importer.ClassFileImporter()
            .importPath(
                java.nio.file.Path.of(
                    Cameras.class.getProtectionDomain().getCodeSource().getLocation().toURI()));
    assertTrue(classes.size() > 30, "acts-vision's classes were found: " + classes.size());
    com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses()
        .should()
        .dependOnClassesThat()
        .resideInAnyPackage("org.opencv..", "nu.pattern..")
        .check(classes);
  }
}
