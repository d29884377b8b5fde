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
 * OpenCV is an optional dependency of acts-vision: only the live camera may reach it, so that a
 * program speaking the ACTS protocol, or tracking still images or the simulator's camera, runs
 * without the OpenCV jar, and one that opens a camera without it is told which library to add.
 */
class OpenCvConfinementTest {

  private static Path classes() throws Exception {
    return Path.of(OpenCvLoader.class.getProtectionDomain().getCodeSource().getLocation().toURI());
  }

  @Test
  void onlyTheCameraAndTheLoaderUseOpenCv() throws Exception {
    JavaClasses acts = new ClassFileImporter().importPath(classes());
    assertTrue(acts.size() > 40, "acts-vision's classes were found: " + acts.size());
    noClasses()
        .that()
        .doNotHaveFullyQualifiedName(CameraSource.class.getName())
        .and()
        .doNotHaveFullyQualifiedName(OpenCvLoader.class.getName())
        .and()
        .doNotHaveFullyQualifiedName(OpenCvLoader.class.getName() + "$Outcome")
        .should()
        .dependOnClassesThat()
        .resideInAnyPackage("org.opencv..", "nu.pattern..")
        .because("OpenCV is optional: only a live camera needs it")
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
  void everyOtherClassLoadsWithoutOpenCvAndACameraSaysWhatToAdd() throws Exception {
    List<URL> path = new ArrayList<>();
    path.add(OpenCvLoader.class.getProtectionDomain().getCodeSource().getLocation());
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
              .filter(f -> f.endsWith(".class") && !f.contains("CameraSource"))
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
      Class<?> camera = noOpenCv.loadClass(CameraSource.class.getName());
      InvocationTargetException e =
          assertThrows(
              InvocationTargetException.class,
              () ->
                  camera
                      .getMethod("open", String.class, int.class, int.class)
                      .invoke(null, "0", 160, 120));
      assertTrue(e.getCause() instanceof IOException, String.valueOf(e.getCause()));
      assertTrue(
          e.getCause().getMessage().contains("org.openpnp:opencv"), e.getCause().getMessage());
    }
  }
}
