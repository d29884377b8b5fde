package org.jaria.apps.fx;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** How a picture reaches its file: whole, and with the permissions of any new file. */
class FxImagesTest {

  @Test
  void aScreenshotGetsTheUsersUsualPermissionsNotATempFilesPrivateOnes(@TempDir Path dir)
      throws IOException {
    Path usual = Files.write(dir.resolve("usual.txt"), new byte[] {1}); // the umask's permissions
    Set<PosixFilePermission> expected = Files.getPosixFilePermissions(usual);
    Path png = dir.resolve("shots/monitor.png");
    FxImages.write(new byte[] {1, 2, 3}, png);
    assertArrayEquals(new byte[] {1, 2, 3}, Files.readAllBytes(png));
    assertEquals(expected, Files.getPosixFilePermissions(png));
    assertTrue(expected.contains(PosixFilePermission.OWNER_READ), expected.toString());
    try (var files = Files.list(png.getParent())) {
      assertEquals(1, files.count(), "nothing left beside it");
    }
  }
}
