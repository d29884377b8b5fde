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
import org.junit.jupiter.api.Test;

/**
 * ArRobot's public methods and constructors are the ones ARIA programs port to; however the class
 * is split inside, the set must stay exactly the one in {@code ArRobot-public-api.txt}.
 *
 * <p>After a deliberate API change, regenerate the list with {@code -Djaria.api.update=true} and
 * review the diff.
 */
class ArRobotApiTest {

  private static final String GOLDEN = "ArRobot-public-api.txt";

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
  void publicMethodSetIsTheGoldenList() throws IOException {
    List<String> now = publicSignatures(ArRobot.class);
    if (Boolean.getBoolean("jaria.api.update")) {
      Path file = Path.of("src/test/resources/org/jaria/robot", GOLDEN);
      Files.write(file, now, StandardCharsets.UTF_8);
    }
    List<String> golden;
    try (InputStream in = ArRobotApiTest.class.getResourceAsStream(GOLDEN)) {
      golden = new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().toList();
    }
    assertEquals(String.join("\n", golden), String.join("\n", now));
  }
}
