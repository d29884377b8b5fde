package org.jaria.acts.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import org.jaria.acts.ActsFormatException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ActsPreferencesTest {

  @Test
  void defaultsAreThoseOfTheThesis() {
    ActsPreferences d = ActsPreferences.DEFAULT;
    assertEquals(5, d.minBlobSize());
    assertEquals(160, d.width());
    assertEquals(120, d.height());
    assertEquals(5001, d.port());
    assertEquals("-1", d.grabberDevice());
    assertEquals(30, d.framesPerSecond());
    assertTrue(d.showGraphics());
    assertEquals(false, d.palCamera());
    assertEquals(false, d.invertedImage());
    assertEquals(1, d.grabberChannel());
  }

  @Test
  void roundTripsThroughAFile(@TempDir Path dir) throws IOException {
    ActsPreferences p =
        new ActsPreferences(
            "my test.ppm",
            "actsconfig",
            7,
            320,
            240,
            5005,
            "opencv",
            "/dev/video1",
            15,
            false,
            true,
            false,
            true,
            2);
    Path f = dir.resolve("ACTS.pref");
    p.write(f);
    assertEquals(p, ActsPreferences.read(f));
  }

  @Test
  void partialFileKeepsOtherDefaults() throws ActsFormatException {
    ActsPreferences p = ActsPreferences.parse("Port 6001\nInvertedImage yes\n", "p");
    assertEquals(6001, p.port());
    assertTrue(p.invertedImage());
    assertEquals(160, p.width());
  }

  @Test
  void errorsNameTheLine() {
    ActsFormatException e =
        assertThrows(
            ActsFormatException.class,
            () -> ActsPreferences.parse("Port 1\nShowGraphics maybe\n", "ACTS.pref"));
    assertTrue(
        e.getMessage().startsWith("ACTS.pref:2: ShowGraphics needs true or false"), e.getMessage());
    e = assertThrows(ActsFormatException.class, () -> ActsPreferences.parse("Colour red\n", "p"));
    assertTrue(e.getMessage().contains("unknown preference 'Colour'"), e.getMessage());
  }
}
