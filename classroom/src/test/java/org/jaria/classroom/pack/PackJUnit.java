package org.jaria.classroom.pack;

import java.io.IOException;
import java.net.URISyntaxException;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.jaria.classroom.grading.SubmissionCompiler;
import org.junit.platform.engine.discovery.DiscoverySelectors;
import org.junit.platform.launcher.Launcher;
import org.junit.platform.launcher.LauncherDiscoveryRequest;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;
import org.junit.platform.launcher.listeners.SummaryGeneratingListener;
import org.junit.platform.launcher.listeners.TestExecutionSummary;

/**
 * Runs the JUnit test a pack carries in its test/ folder, as a teacher's IDE would: compiled
 * against JAria, JUnit and the pack's classes, run by the JUnit platform with the pack's folder as
 * {@code jaria.pack}.
 */
final class PackJUnit {

  private PackJUnit() {}

  /** Runs the tests in {@code pack}/test against {@code packs} (which loaded that pack). */
  static TestExecutionSummary run(Path pack, Packs packs, Path work)
      throws IOException, ClassNotFoundException, URISyntaxException {
    List<String> cp = new ArrayList<>();
    cp.add(SubmissionCompiler.classPath());
    cp.add(location(org.junit.jupiter.api.Test.class));
    cp.add(location(org.opentest4j.AssertionFailedError.class));
    cp.add(location(org.apiguardian.api.API.class));
    for (var u : packs.loader().getURLs()) {
      cp.add(Path.of(u.toURI()).toString());
    }
    Path classes = work.resolve("test-classes");
    SubmissionCompiler.Result r =
        SubmissionCompiler.compile(
            pack.resolve("test"), classes, String.join(java.io.File.pathSeparator, cp));
    if (!r.ok()) {
      throw new AssertionError("the pack's test does not compile:\n" + r.errors());
    }
    List<String> names;
    try (Stream<Path> s = Files.walk(classes)) {
      names =
          s.filter(p -> p.toString().endsWith("Test.class"))
              .map(p -> classes.relativize(p).toString().replace('/', '.').replace(".class", ""))
              .toList();
    }
    String before = System.getProperty("jaria.pack");
    System.setProperty("jaria.pack", pack.toAbsolutePath().toString());
    // the test and the pack's classes in one loader, as on an IDE's class path (a test may use the
    // pack's package-private classes)
    List<java.net.URL> urls = new ArrayList<>(List.of(packs.loader().getURLs()));
    urls.add(classes.toUri().toURL());
    try (URLClassLoader loader =
        new URLClassLoader(urls.toArray(java.net.URL[]::new), Packs.class.getClassLoader())) {
      LauncherDiscoveryRequestBuilder b = LauncherDiscoveryRequestBuilder.request();
      for (String n : names) {
        b.selectors(DiscoverySelectors.selectClass(Class.forName(n, false, loader)));
      }
      LauncherDiscoveryRequest req = b.build();
      Launcher launcher = LauncherFactory.create();
      SummaryGeneratingListener listener = new SummaryGeneratingListener();
      launcher.execute(req, listener);
      return listener.getSummary();
    } finally {
      if (before == null) {
        System.clearProperty("jaria.pack");
      } else {
        System.setProperty("jaria.pack", before);
      }
    }
  }

  private static String location(Class<?> c) throws URISyntaxException {
    return Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
  }
}
