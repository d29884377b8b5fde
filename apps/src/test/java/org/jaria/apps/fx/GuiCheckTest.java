package org.jaria.apps.fx;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** The GUI prerequisites, decided over values: one line, with the fix. */
class GuiCheckTest {

  private static final List<String> DIRS = GuiCheck.libraryDirs(null, "amd64");

  @Test
  void aLinuxDesktopWithGtkNeedsNothing() {
    assertEquals(
        Optional.empty(),
        GuiCheck.problem(
            "Linux", Map.of("DISPLAY", ":0"), d -> d.endsWith("x86_64-linux-gnu"), DIRS));
  }

  @Test
  void missingGtkSaysWhichPackageToInstall() {
    String p = GuiCheck.problem("Linux", Map.of("DISPLAY", ":0"), d -> false, DIRS).orElseThrow();
    assertTrue(p.contains("GTK 3") && p.contains("apt-get install libgtk-3-0"), p);
    assertTrue(!p.contains("DISPLAY"), "the display is fine, so it is not blamed: " + p);
  }

  @Test
  void noDisplaySaysHowToGetOne() {
    String p = GuiCheck.problem("Linux", Map.of(), d -> true, DIRS).orElseThrow();
    assertTrue(p.contains("DISPLAY is not set") && p.contains("xvfb-run"), p);
    assertEquals(
        Optional.empty(),
        GuiCheck.problem("Linux", Map.of("WAYLAND_DISPLAY", "wayland-0"), d -> true, DIRS));
  }

  @Test
  void neitherSaysBothInOneLine() {
    String p = GuiCheck.problem("Linux", Map.of(), d -> false, DIRS).orElseThrow();
    assertTrue(p.contains("libgtk-3-0 xvfb") && !p.contains("\n"), p);
  }

  @Test
  void otherSystemsAreNotChecked() {
    assertEquals(Optional.empty(), GuiCheck.problem("Mac OS X", Map.of(), d -> false, DIRS));
    assertEquals(Optional.empty(), GuiCheck.problem("Windows 11", Map.of(), d -> false, DIRS));
  }

  @Test
  void theLinkersFoldersIncludeLdLibraryPathAndTheMultiarchFolder() {
    List<String> dirs = GuiCheck.libraryDirs("/opt/gtk/lib", "amd64");
    assertEquals("/opt/gtk/lib", dirs.get(0));
    assertTrue(dirs.contains("/usr/lib/x86_64-linux-gnu"), dirs.toString());
  }
}
