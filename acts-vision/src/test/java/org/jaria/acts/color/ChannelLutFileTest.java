package org.jaria.acts.color;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.SplittableRandom;
import org.jaria.acts.ActsFormatException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class ChannelLutFileTest {

  @TempDir Path dir;

  private static Channel sample(int bits) {
    Channel c = new Channel(bits);
    SplittableRandom r = new SplittableRandom(bits);
    for (int i = 0; i < 20; i++) {
      c.addColor(r.nextInt(1 << 24), r.nextInt(0, 12));
    }
    c.setLimits(ColorPlane.BG, new PlaneLimits(3, 4, 5, 480));
    return c;
  }

  @ParameterizedTest
  @ValueSource(ints = {4, 5, 6, 7, 8})
  void roundTripsEveryResolution(int bits) throws IOException {
    Channel c = sample(bits);
    Path f = dir.resolve("channel1.lut");
    ChannelLutFile.write(c, f);
    Channel back = ChannelLutFile.read(f);
    assertTrue(back.contentEquals(c));
    assertEquals(
        3 * (1 << (2 * bits)) / 8, Files.size(f) - headerAndTrailerLength(Files.readAllBytes(f)));
  }

  private static int headerAndTrailerLength(byte[] file) {
    String s = new String(file, StandardCharsets.ISO_8859_1);
    int planes = s.indexOf("planes ");
    int dataStart = s.indexOf('\n', planes) + 1;
    int crc = s.lastIndexOf("crc32 ");
    return dataStart + (file.length - crc) + 1; // +1: the newline after the planes
  }

  @Test
  void headerIsReadableText() {
    String s = new String(ChannelLutFile.toBytes(sample(6)), StandardCharsets.ISO_8859_1);
    assertTrue(s.startsWith("JARIA-ACTS-LUT 1\n# "), s.substring(0, 40));
    assertTrue(s.contains("\ncells 64\nlimits RG 0 0 0 510\nlimits BG 3 4 5 480\n"));
    assertTrue(s.contains("\nplanes 1536\n"));
    assertTrue(s.matches("(?s).*\ncrc32 [0-9A-F]{8}\n$"));
  }

  @Test
  void damagedFilesGiveClearErrors() {
    byte[] good = ChannelLutFile.toBytes(sample(6));
    String name = "channel3.lut";
    assertMessage(
        () -> ChannelLutFile.parse("hello\n".getBytes(StandardCharsets.US_ASCII), name),
        "channel3.lut:1: not a JAria channel LUT file");
    assertMessage(() -> ChannelLutFile.parse(Arrays.copyOf(good, 300), name), "truncated");
    assertMessage(() -> ChannelLutFile.parse(Arrays.copyOf(good, 20), name), "truncated");
    byte[] flipped = good.clone();
    flipped[good.length / 2] ^= 0x10;
    assertMessage(() -> ChannelLutFile.parse(flipped, name), "checksum mismatch");
    byte[] badCells =
        new String(good, StandardCharsets.ISO_8859_1)
            .replace("cells 64", "cells 48")
            .getBytes(StandardCharsets.ISO_8859_1);
    assertMessage(() -> ChannelLutFile.parse(badCells, name), "channel3.lut:3: cells must be");
    byte[] extra = Arrays.copyOf(good, good.length + 1);
    assertMessage(() -> ChannelLutFile.parse(extra, name), "after the checksum");
  }

  private static void assertMessage(ThrowingRunnable r, String expected) {
    try {
      r.run();
      fail("expected an error containing '" + expected + "'");
    } catch (ActsFormatException e) {
      assertTrue(e.getMessage().contains(expected), e.getMessage());
    } catch (Exception e) {
      fail("expected an ActsFormatException, got " + e);
    }
  }

  interface ThrowingRunnable {
    void run() throws Exception;
  }

  /**
   * Seeded fuzzing: random byte changes, insertions, deletions and truncations of a valid file are
   * either rejected with an ActsFormatException or (never, in practice, thanks to the checksum)
   * decoded; loading through a trainer leaves the channel untouched on failure.
   */
  @Test
  void fuzzedFilesNeverCrashAndNeverChangeTheChannel() throws IOException {
    byte[] good = ChannelLutFile.toBytes(sample(5));
    ChannelBank bank = new ChannelBank(5);
    Trainer trainer = new Trainer(bank);
    Channel current = sample(5);
    current.addColor(0x010203, 0);
    bank.replace(1, current);
    SplittableRandom r = new SplittableRandom(2024);
    int rejected = 0;
    for (int i = 0; i < 3000; i++) {
      byte[] bad = mutate(good, r);
      try {
        Channel c = ChannelLutFile.read(new ByteArrayInputStream(bad), "fuzz.lut");
        trainer.load(c);
        trainer.undo();
      } catch (ActsFormatException e) {
        rejected++;
        assertTrue(e.getMessage().startsWith("fuzz.lut"), e.getMessage());
      }
      assertTrue(bank.copyOf(1).contentEquals(current), "iteration " + i);
    }
    assertTrue(rejected > 2900, "rejected " + rejected);
  }

  private static byte[] mutate(byte[] good, SplittableRandom r) {
    byte[] b = good.clone();
    switch (r.nextInt(5)) {
      case 0 -> b[r.nextInt(b.length)] ^= (byte) (1 << r.nextInt(8));
      case 1 -> b = Arrays.copyOf(b, r.nextInt(b.length));
      case 2 -> {
        int at = r.nextInt(b.length);
        byte[] c = new byte[b.length + 1];
        System.arraycopy(b, 0, c, 0, at);
        c[at] = (byte) r.nextInt(256);
        System.arraycopy(b, at, c, at + 1, b.length - at);
        b = c;
      }
      case 3 -> {
        int at = r.nextInt(b.length);
        byte[] c = new byte[b.length - 1];
        System.arraycopy(b, 0, c, 0, at);
        System.arraycopy(b, at + 1, c, at, b.length - at - 1);
        b = c;
      }
      default -> {
        for (int k = 0; k < 1 + r.nextInt(20); k++) {
          b[r.nextInt(Math.min(b.length, 200))] = (byte) r.nextInt(256);
        }
      }
    }
    return b;
  }

  @Test
  void randomBytesAreRejected() {
    SplittableRandom r = new SplittableRandom(7);
    for (int i = 0; i < 500; i++) {
      byte[] b = new byte[r.nextInt(0, 2000)];
      for (int k = 0; k < b.length; k++) {
        b[k] = (byte) r.nextInt(256);
      }
      assertThrows(ActsFormatException.class, () -> ChannelLutFile.parse(b, "random.lut"));
    }
  }

  @Test
  void writeReplacesAtomicallyAndBytesAreDeterministic() throws IOException {
    Channel c = sample(8);
    Path f = dir.resolve("x.lut");
    ChannelLutFile.write(c, f);
    ChannelLutFile.write(c, f);
    assertArrayEquals(ChannelLutFile.toBytes(c), Files.readAllBytes(f));
    try (var s = Files.list(dir)) {
      assertEquals(1, s.count(), "no temporary file left behind");
    }
  }

  @Test
  void oversizedFileIsRefusedBeforeReading() throws IOException {
    Path f = dir.resolve("huge.lut");
    Files.write(f, new byte[ChannelLutFile.MAX_FILE_BYTES + 1]);
    ActsFormatException e = assertThrows(ActsFormatException.class, () -> ChannelLutFile.read(f));
    assertTrue(e.getMessage().contains("too large"), e.getMessage());
  }
}
