package org.jaria.acts.color;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class ChannelBankTest {

  /** The compiled tables give, for every pixel, the mask of the channels' reference answers. */
  @ParameterizedTest
  @ValueSource(ints = {4, 6, 7, 8})
  void tablesAgreeWithEachChannelsReferenceClassification(int bits) {
    ChannelBank bank = new ChannelBank(bits);
    SplittableRandom r = new SplittableRandom(bits);
    for (int ch = 1; ch <= 32; ch++) {
      int seed = r.nextInt();
      bank.edit(
          ch,
          c -> {
            SplittableRandom cr = new SplittableRandom(seed);
            for (int i = 0; i < 6; i++) {
              c.addColor(cr.nextInt(1 << 24), cr.nextInt(0, 40));
            }
            if (cr.nextBoolean()) {
              c.setLimits(ColorPlane.values()[cr.nextInt(3)], new PlaneLimits(10, 20, 50, 450));
            }
            return null;
          });
    }
    LookupTables t = bank.tables();
    int[] pixels = new int[50_000];
    for (int i = 0; i < pixels.length; i++) {
      pixels[i] = r.nextInt(1 << 24);
    }
    int[] masks = new int[pixels.length];
    t.classify(pixels, masks, pixels.length);
    int hits = 0;
    for (int i = 0; i < pixels.length; i++) {
      int expected = 0;
      for (int ch = 1; ch <= 32; ch++) {
        if (bank.copyOf(ch).classifies(pixels[i])) {
          expected |= 1 << (ch - 1);
        }
      }
      assertEquals(expected, masks[i], "pixel " + Integer.toHexString(pixels[i]));
      hits += expected != 0 ? 1 : 0;
      if (i > 2000) {
        break; // the reference path is slow; the rest is checked against the fast path below
      }
    }
    assertTrue(hits > 10, "the random training should classify some pixels");
    for (int i = 0; i < pixels.length; i++) {
      assertEquals(t.classify(pixels[i]), masks[i]);
    }
  }

  @Test
  void tablesAreCachedUntilTheNextEdit() {
    ChannelBank bank = new ChannelBank();
    LookupTables a = bank.tables();
    assertSame(a, bank.tables());
    long v = bank.version();
    bank.edit(
        5,
        c -> {
          c.addColor(0x112233, 0);
          return null;
        });
    assertTrue(bank.version() > v);
    LookupTables b = bank.tables();
    assertNotSame(a, b);
    assertEquals(0, a.classify(0x112233), "an old snapshot never changes");
    assertEquals(1 << 4, b.classify(0x112233));
    assertEquals(1 << 4, b.activeMask());
  }

  @Test
  void aChannelNeedsAllThreePlanesToBeActive() {
    ChannelBank bank = new ChannelBank();
    bank.edit(
        2,
        c -> {
          c.fillPlane(ColorPlane.RG);
          c.fillPlane(ColorPlane.BG);
          return null;
        });
    assertEquals(0, bank.activeMask());
    bank.edit(
        2,
        c -> {
          c.fillPlane(ColorPlane.RB);
          return null;
        });
    assertEquals(0b10, bank.activeMask());
    assertEquals(0b10, bank.tables().classify(0xABCDEF));
  }

  @Test
  void trackedBlobsAndFileNames() {
    ChannelBank bank = new ChannelBank();
    assertEquals(3, bank.getTrackedBlobs(7));
    assertEquals("channel7.lut", bank.getFileName(7));
    bank.setTrackedBlobs(7, 10);
    assertEquals(10, bank.tables().trackedBlobs(7));
    assertThrows(IllegalArgumentException.class, () -> bank.setTrackedBlobs(7, 11));
    assertThrows(IllegalArgumentException.class, () -> bank.setTrackedBlobs(7, 0));
    assertThrows(IllegalArgumentException.class, () -> bank.getTrackedBlobs(33));
    assertThrows(IllegalArgumentException.class, () -> bank.getTrackedBlobs(0));
  }

  @Test
  void replaceResamplesAndReplaceAllIsAllOrNothing() {
    ChannelBank bank = new ChannelBank(6);
    Channel fine = new Channel(8);
    fine.addColor(0x804020, 0);
    bank.replace(1, fine);
    assertEquals(1, bank.tables().classify(0x804020));

    Channel[] contents = new Channel[32];
    int[] tracked = new int[32];
    java.util.Arrays.fill(tracked, 3);
    tracked[4] = 99; // invalid
    assertThrows(
        IllegalArgumentException.class, () -> bank.replaceAll(contents, tracked, new String[32]));
    assertEquals(1, bank.tables().classify(0x804020), "unchanged after a rejected replaceAll");
    tracked[4] = 2;
    bank.replaceAll(contents, tracked, new String[32]);
    assertEquals(0, bank.tables().classify(0x804020));
    assertEquals(2, bank.getTrackedBlobs(5));
  }
}
