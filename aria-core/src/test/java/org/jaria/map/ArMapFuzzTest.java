package org.jaria.map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Seeded random damage to real maps: truncation, flipped bytes, random bytes, inserted garbage
 * lines. Reading must succeed or fail with a MapFormatException naming the source and a line;
 * whatever reads must write and read back to an equal map.
 */
class ArMapFuzzTest {

  private static final String[] GARBAGE = {
    "Cairn: Goal abc 5 0 \"\" ICON \"x\"",
    "Cairn: \"",
    "LINES",
    "DATA",
    "1 2 3",
    "1",
    "x y",
    "MapInfo: \"",
    "MapInfo:",
    "Resolution: -",
    "\u0000\u0007",
    "Cairn: Dock 1 2 3 \"\" ICON \"d\" 4",
    "2D-Map",
    "   ",
    "NumPoints: 1e12",
    "-- -- --",
    "Cairn: Goal 1e999 0 0 \"\" ICON \"big\"",
    "_Cairn: whatever",
    "9999999999999999999999 1"
  };

  @Test
  void damagedMapsFailCleanlyOrRoundTrip() throws Exception {
    Random rnd = new Random(7_000_001L);
    byte[] triangle = Files.readAllBytes(ReferenceMaps.path("triangle.map"));
    byte[] columbia = Files.readAllBytes(ReferenceMaps.path("columbia.map"));
    // The header and first rows of columbia keep each round fast but still hit every part.
    byte[] columbiaHead = Arrays.copyOf(columbia, 40_000);
    byte[] office;
    try (var in = ArMap.class.getResourceAsStream("/org/jaria/maps/office.map")) {
      office = in.readAllBytes();
    }
    int ok = 0;
    int rejected = 0;
    byte[][] inputs = {triangle, columbiaHead, office, columbia};
    int[] rounds = {400, 400, 200, 10};
    for (int k = 0; k < inputs.length; k++) {
      for (int round = 0; round < rounds[k]; round++) {
        String source = "fuzz" + k + "-" + round;
        String text = new String(mutate(inputs[k], rnd), StandardCharsets.ISO_8859_1);
        ArMap m;
        try {
          m = ReferenceMaps.parseAs(text, source);
        } catch (MapFormatException e) {
          assertEquals(source, e.getSourceName());
          assertTrue(e.getLine() >= 1, e.getMessage());
          assertTrue(e.getMessage().startsWith(source + ":" + e.getLine() + ": "));
          rejected++;
          continue;
        } catch (RuntimeException e) {
          fail(source + " threw " + e, e);
          return;
        }
        ok++;
        String written = ReferenceMaps.write(m);
        assertEquals(text, written, source + " did not round trip");
        assertEquals(m, ReferenceMaps.parseAs(written, source));
      }
    }
    assertTrue(ok > 100, "too few mutations survived: " + ok);
    assertTrue(rejected > 100, "too few mutations were rejected: " + rejected);
  }

  private static byte[] mutate(byte[] in, Random rnd) {
    byte[] d = in.clone();
    switch (rnd.nextInt(4)) {
      case 0 -> d = Arrays.copyOf(d, rnd.nextInt(d.length));
      case 1 -> {
        int flips = 1 + rnd.nextInt(6);
        for (int i = 0; i < flips; i++) {
          d[rnd.nextInt(d.length)] ^= (byte) (1 << rnd.nextInt(8));
        }
      }
      case 2 -> {
        String s = new String(d, StandardCharsets.ISO_8859_1);
        int at = s.indexOf('\n', rnd.nextInt(s.length())) + 1;
        String g = GARBAGE[rnd.nextInt(GARBAGE.length)];
        d = (s.substring(0, at) + g + "\n" + s.substring(at)).getBytes(StandardCharsets.ISO_8859_1);
      }
      default -> {
        for (int i = 0; i < 2; i++) {
          d[rnd.nextInt(d.length)] = (byte) (32 + rnd.nextInt(95));
        }
      }
    }
    return d;
  }
}
