package org.jaria.acts.image;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.jaria.robot.ArRobot;
import org.junit.jupiter.api.Test;

/**
 * acts-vision has no OpenCV at all: live cameras are the module acts-camera's, so that a program
 * speaking the ACTS protocol, or tracking still images or the simulator's camera, runs without the
 * 110 MB OpenCV jar, and one that opens a camera without acts-camera is told which library to add.
 */
class OpenCvConfinementTest {

  private static Path classes() throws Exception {
    return Path.of(Cameras.class.getProtectionDomain().getCodeSource().getLocation().toURI());
  }

  @Test
  void noClassUsesOpenCv() throws Exception {
    JavaClasses acts = new ClassFileImporter().importPath(classes());
    assertTrue(acts.size() > 40, "acts-vision's classes were found: " + acts.size());
    noClasses()
        .should()
        .dependOnClassesThat()
        .resideInAnyPackage("org.opencv..", "nu.pattern..")
        .because("OpenCV is acts-camera's: only a live camera needs it")
        .check(acts);
  }

  /** The jar (or folder) on this test's class path that holds {@code resource}. */
  private static URL jarOf(String resource) throws Exception {
    URL u = OpenCvConfinementTest.class.getClassLoader().getResource(resource);
    assertTrue(u != null, resource + " is on the test class path");
    String s = u.toString();
    if (s.startsWith("jar:")) {
      return new URL(s.substring(4, s.indexOf("!/")));
    }
    return new URL(s.substring(0, s.length() - resource.length()));
  }

  @Test
  void everyClassLoadsWithoutOpenCvAndACameraSaysWhatToAdd() throws Exception {
    List<URL> path = new ArrayList<>();
    path.add(Cameras.class.getProtectionDomain().getCodeSource().getLocation());
    path.add(ArRobot.class.getProtectionDomain().getCodeSource().getLocation());
    // aria-core's own dependencies, found by name: this test does not use them itself.
    for (String c :
        List.of(
            "org/slf4j/Logger.class",
            "com/fazecast/jSerialComm/SerialPort.class",
            "org/jline/terminal/Terminal.class")) {
      path.add(jarOf(c));
    }
    Path root = classes();
    List<String> names;
    try (Stream<Path> files = Files.walk(root)) {
      names =
          files
              .map(root::relativize)
              .map(Path::toString)
              .filter(f -> f.endsWith(".class"))
              .map(f -> f.substring(0, f.length() - ".class".length()).replace('/', '.'))
              .toList();
    }
    try (URLClassLoader noOpenCv =
        new URLClassLoader(path.toArray(URL[]::new), ClassLoader.getPlatformClassLoader())) {
      assertThrows(
          ClassNotFoundException.class,
          () -> noOpenCv.loadClass("org.opencv.core.Mat"),
          "the loader really has no OpenCV");
      for (String name : names) {
        Class.forName(name, true, noOpenCv); // links and initialises: fails if OpenCV is needed
      }
      Class<?> cameras = noOpenCv.loadClass(Cameras.class.getName());
      InvocationTargetException e =
          assertThrows(
              InvocationTargetException.class,
              () ->
                  cameras
                      .getMethod("open", String.class, int.class, int.class)
                      .invoke(null, "0", 160, 120));
      assertTrue(e.getCause() instanceof IOException, String.valueOf(e.getCause()));
      assertTrue(
          e.getCause().getMessage().contains("org.jaria:acts-camera"), e.getCause().getMessage());
    }
  }
}
