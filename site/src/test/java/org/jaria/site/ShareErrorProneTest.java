package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarOutputStream;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.zip.ZipEntry;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The build's {@code share-error-prone} step (parent/pom.xml, {@code .mvn/share-error-prone}) puts
 * Error Prone on Maven's own class path once, so that the build's compiles stop loading it one by
 * one: it must use the version the compiler's processor path names, leave its own tools' jars out,
 * and work with the JVM options {@code .mvn/jvm.config} gives Maven (and do no harm without them).
 */
class ShareErrorProneTest {

  private static final Path ROOT = Repo.root();
  private static final String PLUGIN = "com.google.errorprone.ErrorProneJavacPlugin";

  @TempDir static Path dir;
  static String exclude;

  @BeforeAll
  static void compileTheStepAndFakeJars() throws IOException {
    String pom = Files.readString(ROOT.resolve("parent/pom.xml"));
    Matcher m =
        Pattern.compile("<share-error-prone jars=\"[^\"]+\"\\s+exclude=\"([^\"]+)\"").matcher(pom);
    assertTrue(m.find(), "the parent pom runs the share-error-prone task with an exclude pattern");
    exclude = m.group(1);
    Path classes = Files.createDirectories(dir.resolve("classes"));
    Files.writeString(
        dir.resolve("Driver.java"),
        """
        public class Driver {
          public static void main(String[] a) throws Exception {
            ShareErrorProne s = new ShareErrorProne();
            s.setJars(a[0]);
            s.setExclude(a[1]);
            s.execute();
            ClassLoader app = ClassLoader.getSystemClassLoader();
            for (String c : new String[] {"com.google.errorprone.ErrorProneJavacPlugin", "Tool"}) {
              try {
                Class.forName(c, false, app);
                System.out.println("loads " + c);
              } catch (ClassNotFoundException e) {
                System.out.println("does not load " + c);
              }
            }
          }
        }
        """);
    Path plugin = dir.resolve("ErrorProneJavacPlugin.java");
    Files.writeString(
        plugin, "package com.google.errorprone;\npublic class ErrorProneJavacPlugin {}\n");
    Path tool = dir.resolve("Tool.java");
    Files.writeString(tool, "public class Tool {}\n");
    Path fakes = Files.createDirectories(dir.resolve("fakes"));
    compile(
        fakes,
        dir.resolve("Driver.java"),
        plugin,
        tool,
        ROOT.resolve(".mvn/share-error-prone/ShareErrorProne.java"));
    for (String c : List.of("ShareErrorProne", "Driver")) {
      Files.move(fakes.resolve(c + ".class"), classes.resolve(c + ".class"));
    }
    jar(
        dir.resolve("error_prone_core-9.9.9.jar"),
        fakes,
        "com/google/errorprone/ErrorProneJavacPlugin.class");
    jar(dir.resolve("ant-1.10.12.jar"), fakes, "Tool.class");
  }

  private static void compile(Path out, Path... sources) throws IOException {
    InProcessJavac.Result r = InProcessJavac.compile(List.of("-d", out.toString()), sources);
    assertTrue(r.ok(), r.log());
  }

  private static void jar(Path jar, Path from, String entry) throws IOException {
    try (OutputStream o = Files.newOutputStream(jar);
        JarOutputStream j = new JarOutputStream(o)) {
      j.putNextEntry(new ZipEntry(entry));
      j.write(Files.readAllBytes(from.resolve(entry)));
      j.closeEntry();
    }
  }

  private static String run(List<String> jvmOptions) throws IOException, InterruptedException {
    List<String> cmd = new ArrayList<>();
    cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
    cmd.addAll(jvmOptions);
    cmd.addAll(
        List.of(
            "-cp",
            dir.resolve("classes").toString(),
            "Driver",
            dir.resolve("error_prone_core-9.9.9.jar")
                + java.io.File.pathSeparator
                + dir.resolve("ant-1.10.12.jar"),
            exclude));
    Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
    String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
    assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the driver ended");
    assertEquals(0, p.exitValue(), out);
    return out;
  }

  @Test
  void itUsesTheProcessorPathsVersionAndMavensJvmGetsTheOptionItNeeds() throws IOException {
    String pom = Files.readString(ROOT.resolve("parent/pom.xml"));
    Matcher processorPath =
        Pattern.compile(
                "<annotationProcessorPaths>\\s*<path>\\s*<groupId>com.google.errorprone</groupId>\\s*"
                    + "<artifactId>error_prone_core</artifactId>\\s*<version>([^<]+)</version>")
            .matcher(pom);
    assertTrue(processorPath.find(), "the compiler's processor path holds error_prone_core");
    Matcher step =
        Pattern.compile(
                "<id>share-error-prone</id>.*?<dependencies>\\s*<dependency>\\s*"
                    + "<groupId>com.google.errorprone</groupId>\\s*"
                    + "<artifactId>error_prone_core</artifactId>\\s*<version>([^<]+)</version>",
                Pattern.DOTALL)
            .matcher(pom);
    assertTrue(step.find(), "the share-error-prone step's plugin depends on error_prone_core");
    assertEquals(processorPath.group(1), step.group(1), "the shared Error Prone's version");
    List<String> jvmConfig = Files.readAllLines(ROOT.resolve(".mvn/jvm.config"));
    assertTrue(
        jvmConfig.contains("--add-opens java.base/jdk.internal.loader=ALL-UNNAMED"),
        "Maven's JVM lets the step add to its class path: " + jvmConfig);
  }

  @Test
  void withMavensOptionsErrorProneLoadsFromTheClassPathAndTheToolsJarsDoNot() throws Exception {
    String out = run(List.of("--add-opens", "java.base/jdk.internal.loader=ALL-UNNAMED"));
    assertTrue(out.contains("loads " + PLUGIN), out);
    assertTrue(out.contains("does not load Tool"), out);
    assertFalse(out.contains("not shared"), out);
  }

  @Test
  void withoutThemItSaysSoAndTheBuildGoesOn() throws Exception {
    String out = run(List.of());
    assertTrue(out.contains("Error Prone is not shared between compiles"), out);
    assertTrue(out.contains("does not load " + PLUGIN), out);
  }
}
