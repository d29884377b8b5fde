import java.io.File;
import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.List;

/**
 * Puts Error Prone on the application class path of Maven's own JVM, once, before the first module
 * compiles: the parent pom's {@code share-error-prone} step runs it as an Ant task (Ant calls the
 * setters, then {@link #execute}).
 *
 * <p>Why: javac runs inside Maven's JVM and makes a new class loader for its processor path in
 * every compile, so each of the build's thirty-odd compiles loaded Error Prone's classes (about two
 * thousand, and Guava's, protobuf's...) again and compiled them to machine code again: more CPU
 * than javac's own work. That class loader asks the application class loader first, where javac
 * itself lives; with the same jars there, every compile uses the one copy the first one loaded.
 * The jars are the ones the compiler would use (the same {@code errorprone.version}), so the checks
 * and what they find do not change.
 *
 * <p>Needs {@code --add-opens java.base/jdk.internal.loader=ALL-UNNAMED} (in {@code
 * .mvn/jvm.config}). Without it, or on a JVM that has no such method, it says so and the build goes
 * on as before: each compile loads Error Prone itself.
 */
public final class ShareErrorProne {

  private static final String PLUGIN = "com.google.errorprone.ErrorProneJavacPlugin";

  private String jars = "";
  private String exclude = "";

  /** The jars of the step's plugin: Error Prone's and the step's own tools (a path list). */
  public void setJars(String jars) {
    this.jars = jars;
  }

  /** A regular expression matching the file names of the step's own tools' jars. */
  public void setExclude(String exclude) {
    this.exclude = exclude;
  }

  /** Appends Error Prone's jars to the application class path. */
  public void execute() throws ReflectiveOperationException {
    List<String> errorProne = new ArrayList<>();
    for (String jar : jars.split(File.pathSeparator)) {
      if (!jar.isEmpty() && !new File(jar).getName().matches(exclude)) {
        errorProne.add(jar);
      }
    }
    if (errorProne.isEmpty()) {
      throw new IllegalStateException(
          "no Error Prone jar among " + jars + ": check the share-error-prone step's exclude");
    }
    ClassLoader app = ClassLoader.getSystemClassLoader();
    if (isLoadable(app)) {
      // a second build in a JVM that stays between builds (a build daemon): shared already, but
      // perhaps another version than this build asks for
      String from =
          Class.forName(PLUGIN, false, app)
              .getProtectionDomain()
              .getCodeSource()
              .getLocation()
              .getPath();
      if (errorProne.stream().noneMatch(j -> new File(j).toURI().getPath().equals(from))) {
        System.out.println(
            "This JVM holds another Error Prone ("
                + from
                + "): restart it to check with "
                + errorProne.get(0));
      }
      return;
    }
    Method append;
    try {
      append =
          app.getClass().getDeclaredMethod("appendToClassPathForInstrumentation", String.class);
      append.setAccessible(true);
    } catch (ReflectiveOperationException | RuntimeException e) {
      System.out.println(
          "Error Prone is not shared between compiles ("
              + e
              + "); each compile loads it itself, which takes longer.");
      return;
    }
    for (String jar : errorProne) {
      append.invoke(app, jar);
    }
    if (!isLoadable(app)) {
      throw new IllegalStateException(
          "Error Prone's jars were added to Maven's class path but its plugin class does not load"
              + " from there: check the share-error-prone step in parent/pom.xml. Jars: "
              + errorProne);
    }
  }

  private static boolean isLoadable(ClassLoader app) {
    try {
      Class.forName(PLUGIN, false, app);
      return true;
    } catch (ClassNotFoundException e) {
      return false;
    }
  }
}
