package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.Constructor;
import java.lang.reflect.Executable;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.Type;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.TreeSet;
import java.util.stream.Collectors;
import org.jaria.params.ArRobotParams;
import org.junit.jupiter.api.Test;

/**
 * ArRobot's and ArRobotParams' public methods and constructors are the ones ARIA programs port to;
 * however the classes are split inside, each set must stay exactly the one in its golden list
 * ({@code ArRobot-public-api.txt}, {@code ArRobotParams-public-api.txt}, next to this test).
 *
 * <p>After a deliberate API change, regenerate the list with {@code -Djaria.api.update=true} and
 * review the diff.
 */
class ArRobotApiTest {

  /** One line per public constructor and method (inherited ones too), sorted. */
  static List<String> publicSignatures(Class<?> c) {
    TreeSet<String> out = new TreeSet<>();
    for (Constructor<?> k : c.getConstructors()) {
      out.add("new " + c.getSimpleName() + params(k));
    }
    for (Method m : c.getMethods()) {
      if (m.isSynthetic() || m.isBridge()) {
        continue;
      }
      String stat = Modifier.isStatic(m.getModifiers()) ? "static " : "";
      out.add(stat + m.getGenericReturnType().getTypeName() + " " + m.getName() + params(m));
    }
    return new ArrayList<>(out);
  }

  private static String params(Executable e) {
    String p =
        Arrays.stream(e.getGenericParameterTypes())
            .map(Type::getTypeName)
            .collect(Collectors.joining(", ", "(", ")"));
    Class<?>[] ex = e.getExceptionTypes();
    if (ex.length == 0) {
      return p;
    }
    return p
        + " throws "
        + Arrays.stream(ex).map(Class::getName).sorted().collect(Collectors.joining(", "));
  }

  @Test
  void arRobotPublicMethodSetIsTheGoldenList() throws IOException {
    assertGolden(ArRobot.class, "ArRobot-public-api.txt");
  }

  @Test
  void arRobotParamsPublicMethodSetIsTheGoldenList() throws IOException {
    assertGolden(ArRobotParams.class, "ArRobotParams-public-api.txt");
  }

  private static void assertGolden(Class<?> c, String golden) throws IOException {
    List<String> now = publicSignatures(c);
    if (Boolean.getBoolean("jaria.api.update")) {
      Files.write(
          Path.of("src/test/resources/org/jaria/robot", golden), now, StandardCharsets.UTF_8);
    }
    List<String> expected;
    try (InputStream in = ArRobotApiTest.class.getResourceAsStream(golden)) {
      if (in == null) {
        throw new IOException(
            golden + " is missing: run this test once with -Djaria.api.update=true");
      }
      expected = new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().toList();
    }
    assertEquals(String.join("\n", expected), String.join("\n", now), c.getName());
  }
}
