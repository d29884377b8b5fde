package org.jaria.classroom.sandbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Students' JVMs never share a user while they run, whether they belong to one grading, to two
 * gradings in one JVM, or to gradings in two JVMs: a thread bomb's process limit is its own.
 */
class SandboxUsersTest {

  @TempDir Path tmp;

  @Test
  void aSlotKeepsItsUserUntilAnotherJvmOfTheMachineHasIt() throws IOException {
    SandboxUsers users = SandboxUsers.in(tmp.resolve("locks"));
    try (SandboxUsers.Lease a = users.lease(0);
        SandboxUsers.Lease b = users.lease(0);
        SandboxUsers.Lease c = users.lease(2)) {
      assertEquals(List.of(64000, 64001, 64002), List.of(a.uid(), b.uid(), c.uid()));
    }
    try (SandboxUsers.Lease again = users.lease(0)) {
      assertEquals(64000, again.uid(), "given back when closed");
    }
    assertEquals(
        "rwx------",
        PosixFilePermissions.toString(Files.getPosixFilePermissions(tmp.resolve("locks"))));
  }

  @Test
  void twoGradersInOneJvmGetDifferentUsersForTheSameSlot() throws IOException {
    SandboxUsers first = SandboxUsers.in(tmp);
    SandboxUsers second = SandboxUsers.in(tmp);
    try (SandboxUsers.Lease a = first.lease(1);
        SandboxUsers.Lease b = second.lease(1)) {
      assertEquals(64001, a.uid());
      assertEquals(64002, b.uid());
    }
  }

  @Test
  void aUserHeldByAnotherJvmIsNotHandedOut() throws Exception {
    String java = ProcessHandle.current().info().command().orElse("java");
    Process other =
        new ProcessBuilder(
                java,
                "-cp",
                System.getProperty("java.class.path"),
                Holder.class.getName(),
                tmp.toString())
            .redirectError(ProcessBuilder.Redirect.INHERIT)
            .start();
    try (BufferedReader out =
        new BufferedReader(new InputStreamReader(other.getInputStream(), StandardCharsets.UTF_8))) {
      assertEquals("64000", out.readLine(), "the other JVM leased slot 0's user");
      try (SandboxUsers.Lease mine = SandboxUsers.in(tmp).lease(0)) {
        assertEquals(64001, mine.uid());
      }
      other.getOutputStream().close(); // lets the holder end, which gives its user back
      assertTrue(other.waitFor(30, TimeUnit.SECONDS));
    } finally {
      other.destroyForcibly();
    }
    try (SandboxUsers.Lease mine = SandboxUsers.in(tmp).lease(0)) {
      assertEquals(64000, mine.uid(), "an ended JVM's lease is gone");
    }
  }

  @Test
  void aLockFolderThatIsALinkIsRefused() throws IOException {
    Path real = Files.createDirectory(tmp.resolve("elsewhere"));
    Path link = Files.createSymbolicLink(tmp.resolve("locks"), real);
    IOException e = assertThrows(IOException.class, () -> SandboxUsers.in(link).lease(0));
    assertTrue(e.getMessage().contains("is not a folder"), e.getMessage());
  }

  @Test
  void aLockFolderOfAnotherUserIsRefused() throws IOException {
    Path locks = Files.createDirectory(tmp.resolve("locks"));
    assumeTrue(
        Integer.valueOf(0).equals(Files.getAttribute(Path.of("/proc/self"), "unix:uid")),
        "giving a folder away needs root");
    Files.setAttribute(locks, "unix:uid", 64999);
    IOException e = assertThrows(IOException.class, () -> SandboxUsers.in(locks).lease(0));
    assertTrue(e.getMessage().contains("belongs to another user (uid 64999)"), e.getMessage());
  }

  /**
   * The other JVM: leases slot 0's user in the folder given, says which, holds it until stdin ends.
   */
  static final class Holder {
    public static void main(String[] args) throws IOException {
      try (SandboxUsers.Lease lease = SandboxUsers.in(Path.of(args[0])).lease(0)) {
        System.out.println(lease.uid());
        System.out.flush();
        while (System.in.read() >= 0) {
          // held until the test closes our standard input
        }
      }
    }
  }
}
