package org.jaria.params;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayInputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Seeded random damage to real parameter files: truncation, flipped bytes, inserted garbage lines.
 * Parsing and typing must either succeed or fail with a ParamFormatException that names a line;
 * nothing else may escape, and nothing may hang.
 */
class ParamFuzzTest {

  private static final String[] GARBAGE = {
    "SonarUnit 0 1",
    "SonarUnit a b c d",
    "IRUnit 1 2 3 4 5 6",
    "RobotRadius",
    "[",
    "Section",
    "\u0000\u0001\u0002",
    "MaxVelocity 1e400",
    "Holonomic perhaps",
    "SonarNum -3",
    "IRNum 99999999999",
    "   ;;;;",
    "= = =",
    "Keyword \"unterminated",
    "ÿÿÿÿ",
    "SonarUnit 5 1 2 3 4"
  };

  @Test
  void damagedFilesFailCleanly() throws Exception {
    Random rnd = new Random(20240229L);
    int ok = 0;
    int rejected = 0;
    for (String subtype : ReferenceParams.SUBTYPES) {
      byte[] original = Files.readAllBytes(ReferenceParams.path(subtype));
      for (int round = 0; round < 100; round++) {
        byte[] data = mutate(original, rnd);
        try (Reader r =
            new InputStreamReader(new ByteArrayInputStream(data), StandardCharsets.ISO_8859_1)) {
          ParamFile f = ParamFile.read(r, subtype + "#" + round);
          ArRobotParams p = ArRobotParams.defaults().overlay(f);
          for (int i = 0; i < p.getNumSonar(); i++) {
            p.getSonarX(i);
          }
          ok++;
        } catch (ParamFormatException e) {
          assertTrue(e.getLine() >= 0 && e.getMessage().startsWith(subtype + "#" + round + ":"));
          rejected++;
        } catch (RuntimeException e) {
          fail(subtype + " round " + round + " threw " + e, e);
        }
      }
    }
    assertTrue(ok > 50, "too few mutations survived: " + ok);
    assertTrue(rejected > 50, "too few mutations were rejected: " + rejected);
  }

  private static byte[] mutate(byte[] in, Random rnd) {
    byte[] d = in.clone();
    switch (rnd.nextInt(4)) {
      case 0 -> d = java.util.Arrays.copyOf(d, rnd.nextInt(d.length));
      case 1 -> {
        int flips = 1 + rnd.nextInt(8);
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
        for (int i = 0; i < 3; i++) {
          d[rnd.nextInt(d.length)] = (byte) rnd.nextInt(256);
        }
      }
    }
    return d;
  }
}
