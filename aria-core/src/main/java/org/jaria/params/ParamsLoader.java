package org.jaria.params;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Optional;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Finds and layers parameter files the way ARIA does when a robot connects. */
final class ParamsLoader {

  private static final Logger LOG = LoggerFactory.getLogger(ArRobotParams.class);

  private ParamsLoader() {}

  /**
   * Generic defaults with the parameter file shipped for {@code subtype} on top (looked up
   * lower-cased, e.g. "p3dx-sh"). An unknown subtype is not an error: a WARN is logged and the
   * generic defaults are returned.
   */
  static ArRobotParams forSubtype(String subtype) {
    Optional<ParamFile> f = bundledFile(subtype);
    if (f.isEmpty()) {
      LOG.warn(
          "No parameter file for robot subtype '{}' (JAria ships {}); using generic Pioneer"
              + " defaults, which define no sonars. Put a {}.p file in the parameter directory to"
              + " describe this robot.",
          subtype,
          ArRobotParams.BUNDLED_SUBTYPES,
          subtype);
      return ArRobotParams.defaults();
    }
    try {
      return ArRobotParams.defaults().overlay(f.get());
    } catch (ParamFormatException e) {
      throw new IllegalStateException("JAria's bundled parameter file is broken: " + e, e);
    }
  }

  /** The parameter file JAria ships for this subtype, if any. */
  static Optional<ParamFile> bundledFile(String subtype) {
    if (subtype == null || !isSafeName(subtype)) {
      return Optional.empty();
    }
    String name = subtype.toLowerCase(Locale.ROOT) + ".p";
    try (InputStream in =
        ParamsLoader.class.getResourceAsStream(ArRobotParams.RESOURCE_DIR + name)) {
      if (in == null) {
        return Optional.empty();
      }
      try (Reader r = new InputStreamReader(in, StandardCharsets.ISO_8859_1)) {
        return Optional.of(ParamFile.read(r, "classpath:" + ArRobotParams.RESOURCE_DIR + name));
      }
    } catch (IOException | ParamFormatException e) {
      throw new IllegalStateException("cannot read JAria's bundled parameter file " + name, e);
    }
  }

  /**
   * The parameters of a connected robot, as ARIA loads them: generic defaults, then {@code
   * <subtype>.p} (from {@code userDir} if there is one there, else the bundled one), then {@code
   * userDir/<robotName>.p} if present. A user {@code <subtype>.p} that cannot be read, parsed or
   * holds impossible values is replaced by JAria's bundled file for the subtype (never by generic
   * defaults, which have no sonar); a bad {@code <robotName>.p} is skipped. Either way the problem
   * is logged as an ERROR naming file and line and kept in {@link ArRobotParams#getProblems()}; use
   * {@link #loadStrict} to get the exception instead.
   *
   * @param subtype the subtype the robot reported (e.g. "p3dx-sh")
   * @param robotName the robot's name from its FLASH, may be null
   * @param userDir folder with the user's parameter files, may be null
   */
  static ArRobotParams load(String subtype, String robotName, Path userDir) {
    ArRobotParams p = null;
    String problem = null;
    Path userSub = userFile(userDir, subtype);
    if (userSub != null) {
      try {
        p = ArRobotParams.defaults().overlay(ParamFile.read(userSub));
        LOG.info("Loaded robot parameters from {}", userSub);
      } catch (ParamFormatException | IOException e) {
        problem = describe(userSub, e);
        LOG.error(
            "{} -- ignoring this parameter file; using JAria's bundled parameters for '{}'"
                + " instead. Fix the line (or remove the file) to use your values.",
            problem,
            subtype);
      }
    }
    if (p == null) {
      p = forSubtype(subtype);
    }
    if (problem != null) {
      p = p.withProblem(problem);
    }
    Path userRobot = userFile(userDir, robotName);
    if (userRobot != null && !userRobot.equals(userSub)) {
      p = overlayLenient(p, userRobot);
    }
    return p;
  }

  private static String describe(Path file, Exception e) {
    return e instanceof ParamFormatException
        ? e.getMessage()
        : file + ": cannot be read (" + e + ")";
  }

  /**
   * Like {@link #load} but a user file that cannot be read or parsed is an error.
   *
   * @throws ParamFormatException if a user file is malformed
   * @throws IOException if a user file exists but cannot be read
   */
  static ArRobotParams loadStrict(String subtype, String robotName, Path userDir)
      throws ParamFormatException, IOException {
    Path userSub = userFile(userDir, subtype);
    ArRobotParams p =
        userSub != null
            ? ArRobotParams.defaults().overlay(ParamFile.read(userSub))
            : forSubtype(subtype);
    Path userRobot = userFile(userDir, robotName);
    if (userRobot != null && !userRobot.equals(userSub)) {
      p = p.overlay(ParamFile.read(userRobot));
    }
    return p;
  }

  private static ArRobotParams overlayLenient(ArRobotParams base, Path file) {
    try {
      ArRobotParams p = base.overlay(ParamFile.read(file));
      LOG.info("Loaded robot parameters from {}", file);
      return p;
    } catch (ParamFormatException | IOException e) {
      String problem = describe(file, e);
      LOG.error("{} -- ignoring this parameter file, keeping the values loaded before it", problem);
      return base.withProblem(problem);
    }
  }

  /** userDir/name.p (or its lower-case spelling) if it is a readable file, else null. */
  private static Path userFile(Path userDir, String name) {
    if (userDir == null || name == null || !isSafeName(name)) {
      return null;
    }
    Path exact = userDir.resolve(name + ".p");
    if (Files.isRegularFile(exact)) {
      return exact;
    }
    Path lower = userDir.resolve(name.toLowerCase(Locale.ROOT) + ".p");
    return Files.isRegularFile(lower) ? lower : null;
  }

  /** Robot names come from the robot; never let one point outside the parameter folder. */
  private static boolean isSafeName(String name) {
    if (name.isBlank() || name.length() > 100 || name.startsWith(".")) {
      return false;
    }
    for (int i = 0; i < name.length(); i++) {
      char c = name.charAt(i);
      if (c == '/' || c == '\\' || c == ':' || c < 0x20) {
        return false;
      }
    }
    return true;
  }
}
