package org.jaria.classroom.sandbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The sandbox's command line as a value: what the student's JVM is given and what it is not. */
class SandboxTest {

  private static final Path SCRATCH = Path.of("/class/report/students/ana/scratch");
  private static final List<Path> CP = List.of(Path.of("/opt/jaria/lib/classroom.jar"));
  private static final Limits LIMITS = Limits.forTimeout(Duration.ofSeconds(30));

  private static List<String> command(Sandbox s, int uid) {
    return s.command(SCRATCH, CP, LIMITS, uid, "Main", List.of("square", "/sandbox/classes"));
  }

  private static boolean hasSequence(List<String> cmd, String... seq) {
    return Collections.indexOfSubList(cmd, List.of(seq)) >= 0;
  }

  @Test
  void asRootTheJvmRunsAsTheUnprivilegedUserItLeasedWithAProcessLimit() {
    List<String> cmd = command(Sandbox.of(true, true), 64002);
    assertEquals("/usr/bin/prlimit", cmd.get(0));
    assertTrue(cmd.contains("--nproc=128"), cmd.toString());
    assertTrue(cmd.contains("--cpu=70"), cmd.toString());
    for (String flag :
        List.of(
            "--unshare-pid", "--unshare-net", "--unshare-ipc", "--die-with-parent", "--clearenv")) {
      assertTrue(cmd.contains(flag), flag + " in " + cmd);
    }
    assertTrue(hasSequence(cmd, "--bind", SCRATCH.toString(), "/sandbox"), cmd.toString());
    assertTrue(
        hasSequence(cmd, "--ro-bind", CP.get(0).toString(), CP.get(0).toString()), cmd.toString());
    assertTrue(cmd.contains("--reuid=64002"), cmd.toString());
    assertTrue(cmd.contains("-Xmx256m"), cmd.toString());
    // nothing of the report or the class is bound but the scratch folder
    assertFalse(
        cmd.stream().anyMatch(a -> a.equals("/class") || a.equals("/class/report")),
        cmd.toString());
    assertEquals(
        List.of("Main", "square", "/sandbox/classes"), cmd.subList(cmd.size() - 3, cmd.size()));
  }

  @Test
  void asRootNoJvmStartsWithoutAUserOfItsOwn() {
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> command(Sandbox.of(true, true), -1));
    assertTrue(e.getMessage().contains("lease one with user(slot)"), e.getMessage());
  }

  @Test
  void withoutRootAUserNamespaceStandsInForTheUser() {
    List<String> cmd = command(Sandbox.of(true, false), -1);
    assertTrue(cmd.contains("--unshare-user"), cmd.toString());
    assertFalse(cmd.stream().anyMatch(a -> a.startsWith("--nproc")), cmd.toString());
    assertFalse(cmd.stream().anyMatch(a -> a.contains("setpriv")), cmd.toString());
  }

  @Test
  void unsafeIsAPlainJvmOnTheScratchFolder() {
    List<String> cmd = command(Sandbox.none(), -1);
    assertTrue(cmd.get(0).endsWith("/bin/java"), cmd.toString());
    assertFalse(cmd.stream().anyMatch(a -> a.contains("bwrap")), cmd.toString());
    assertEquals(SCRATCH + "/classes", cmd.get(cmd.size() - 1));
    assertFalse(Sandbox.none().isolated());
  }
}
