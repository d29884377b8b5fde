package org.jaria.apps.fx;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Predicate;

/**
 * Checks, before JavaFX starts, that a window can open here, and says in one line what to install
 * or set when it cannot. On Linux JavaFX draws through GTK 3 on an X11 (or XWayland) display: a
 * server without GTK or without a display gets one line with the fix instead of JavaFX's stack
 * trace. macOS and Windows need nothing.
 */
public final class GuiCheck {

  /** The library JavaFX's Linux window system loads. */
  static final String GTK_LIBRARY = "libgtk-3.so.0";

  private GuiCheck() {}

  /** What stops a window from opening on this machine, in one line with the fix; empty if none. */
  public static Optional<String> problem() {
    if (FxRuntime.isHeadless()) {
      return Optional.empty();
    }
    return problem(
        System.getProperty("os.name", ""),
        System.getenv(),
        dir -> Files.isRegularFile(Path.of(dir, GTK_LIBRARY)),
        libraryDirs(System.getenv("LD_LIBRARY_PATH"), System.getProperty("os.arch", "")));
  }

  /**
   * The decision, over values.
   *
   * @param os the {@code os.name} property
   * @param env the environment variables
   * @param hasGtk whether a folder holds {@link #GTK_LIBRARY}
   * @param libraryDirs the folders the dynamic linker searches
   */
  static Optional<String> problem(
      String os, Map<String, String> env, Predicate<String> hasGtk, List<String> libraryDirs) {
    if (!os.toLowerCase(Locale.ROOT).contains("linux")) {
      return Optional.empty();
    }
    boolean display = !blank(env.get("DISPLAY")) || !blank(env.get("WAYLAND_DISPLAY"));
    boolean gtk = libraryDirs.stream().anyMatch(hasGtk);
    if (!display && !gtk) {
      return Optional.of(
          "no display and no GTK 3 libraries to open a window with: on a server install both"
              + " (sudo apt-get install libgtk-3-0 xvfb) and run the command under xvfb-run, or"
              + " render the app to a PNG with ./jaria screenshot APP ... -o FILE.png");
    }
    if (!display) {
      return Optional.of(
          "no display to open a window on (DISPLAY is not set): run it on the desktop, over ssh"
              + " -X, or under a virtual display (sudo apt-get install xvfb, then xvfb-run"
              + " ./jaria ...)");
    }
    if (!gtk) {
      return Optional.of(
          "JavaFX needs the GTK 3 libraries, which are not installed: sudo apt-get install"
              + " libgtk-3-0 (Fedora: sudo dnf install gtk3)");
    }
    return Optional.empty();
  }

  /** The folders the Linux dynamic linker searches for a library (the usual ones). */
  static List<String> libraryDirs(String ldLibraryPath, String arch) {
    List<String> dirs = new ArrayList<>();
    if (!blank(ldLibraryPath)) {
      dirs.addAll(List.of(ldLibraryPath.split(File.pathSeparator, -1)));
    }
    String triplet =
        switch (arch) {
          case "amd64", "x86_64" -> "x86_64-linux-gnu";
          case "aarch64", "arm64" -> "aarch64-linux-gnu";
          case "arm" -> "arm-linux-gnueabihf";
          default -> arch + "-linux-gnu";
        };
    for (String base : List.of("/usr/lib", "/lib", "/usr/lib64", "/lib64", "/usr/local/lib")) {
      dirs.add(base + "/" + triplet);
      dirs.add(base);
    }
    return dirs;
  }

  private static boolean blank(String s) {
    return s == null || s.isBlank();
  }
}
