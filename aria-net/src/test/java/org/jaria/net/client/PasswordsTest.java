package org.jaria.net.client;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PasswordsTest {

  @Test
  void fileThenOptionThenEnvironment(@TempDir Path dir) throws Exception {
    Path f = dir.resolve("pw");
    Files.writeString(f, "fromfile\nignored\n");
    Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rw-------"));
    Map<String, String> env = Map.of(Passwords.ENV, "fromenv");
    assertEquals("fromfile", Passwords.resolve(null, f, env));
    assertEquals("opt", Passwords.resolve("opt", null, env));
    assertEquals("fromenv", Passwords.resolve(null, null, env));
    assertNull(Passwords.resolve(null, null, Map.of()));
    assertThrows(IllegalArgumentException.class, () -> Passwords.resolve("a", f, env));
  }

  @Test
  void aPasswordFileOthersMayReadIsRefused(@TempDir Path dir) throws Exception {
    Path f = dir.resolve("pw");
    Files.writeString(f, "secret\n");
    Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rw-r--r--"));
    IOException e = assertThrows(IOException.class, () -> Passwords.resolve(null, f, Map.of()));
    assertTrue(e.getMessage().contains("chmod 600"), e.getMessage());
  }
}
