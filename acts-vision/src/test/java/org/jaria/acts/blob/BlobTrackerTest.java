package org.jaria.acts.blob;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.color.LookupTables;
import org.jaria.acts.image.RgbImage;
import org.jaria.acts.testing.Pictures;
import org.junit.jupiter.api.Test;

class BlobTrackerTest {

  private final ChannelBank bank = Pictures.rgbBank();
  private final BlobTracker tracker = new BlobTracker();
  private final BlobFrame frame = new BlobFrame();

  private BlobFrame track(RgbImage img, TrackerSettings s) {
    tracker.track(img.pixels(), img.width(), img.height(), bank.tables(), s, frame);
    return frame;
  }

  @Test
  void statsOfHandDrawnBlobs() {
    RgbImage img =
        Pictures.draw(
            "..........", ".RRR......", ".RRR...R..", ".RRR...R..", ".......R..", "..........");
    BlobFrame f = track(img, TrackerSettings.ALL_REGIONS);
    assertEquals(2, f.getNumBlobs(1));
    Blob a = f.getBlob(1, 1);
    assertEquals(new Blob(9, 2, 2, 1, 3, 1, 3, 2.0, 2.0), a);
    Blob b = f.getBlob(1, 2);
    assertEquals(3, b.area());
    assertEquals(7, b.left());
    assertEquals(7, b.right());
    assertEquals(2, b.top());
    assertEquals(4, b.bottom());
    assertEquals(3.0, b.yCentroid());
    assertEquals(0, f.getNumBlobs(2));
    assertEquals(10, f.width());
    assertEquals(6, f.height());
  }

  @Test
  void diagonalNeighboursAreSeparateBlobs() {
    // 4-connectivity, as CMVision: runs must overlap on adjacent rows to merge.
    RgbImage img = Pictures.draw("R...", ".R..", "..R.", "...R");
    assertEquals(4, track(img, TrackerSettings.ALL_REGIONS).getNumBlobs(1));
  }

  @Test
  void aUShapeMergesWhenItsArmsJoinLater() {
    RgbImage img =
        Pictures.draw(
            "R...R...R", //
            "R...R...R",
            "R...RRRRR",
            "RRRRR....");
    BlobFrame f = track(img, TrackerSettings.ALL_REGIONS);
    assertEquals(1, f.getNumBlobs(1));
    Blob b = f.getBlob(1, 1);
    assertEquals(3 + 3 + 6 + 5, b.area());
    assertEquals(0, b.left());
    assertEquals(8, b.right());
    assertEquals(0, b.top());
    assertEquals(3, b.bottom());
  }

  @Test
  void holesDoNotSplitABlob() {
    RgbImage img = Pictures.draw("RRRRR", "R...R", "R.R.R", "R...R", "RRRRR");
    BlobFrame f = track(img, TrackerSettings.ALL_REGIONS);
    assertEquals(2, f.getNumBlobs(1), "the ring and the dot inside it");
    assertEquals(16, f.getBlob(1, 1).area());
    assertEquals(new Blob(1, 2, 2, 2, 2, 2, 2, 2.0, 2.0), f.getBlob(1, 2));
  }

  @Test
  void aPixelCanBelongToSeveralChannels() {
    // Yellow is wanted by channel 1 (red-ish) and channel 2 (green-ish); runs of different masks
    // that touch form one run of the channel they share.
    RgbImage img = Pictures.draw("RRYYGG", "......", "..Y...");
    BlobFrame f = track(img, TrackerSettings.ALL_REGIONS);
    assertEquals(2, f.getNumBlobs(1));
    assertEquals(4, f.getBlob(1, 1).area());
    assertEquals(2, f.getNumBlobs(2));
    Blob g = f.getBlob(2, 1);
    assertEquals(4, g.area());
    assertEquals(2, g.left());
    assertEquals(5, g.right());
    assertEquals(0, f.getNumBlobs(3));
  }

  @Test
  void minimumSizeDropsSmallBlobs() {
    RgbImage img =
        Pictures.draw("RRRRR...R.", "RRRRR.....", "RRRRR..RRR", "RRRRR.....", "RRRRR.....");
    assertEquals(3, track(img, TrackerSettings.ALL_REGIONS).getNumBlobs(1));
    BlobFrame f = track(img, TrackerSettings.DEFAULT); // minimum 5 x 5
    assertEquals(1, f.getNumBlobs(1));
    assertEquals(25, f.getBlob(1, 1).area());
    assertEquals(1, track(img, TrackerSettings.ALL_REGIONS.withMinBlobSize(3)).getNumBlobs(1));
    assertEquals(0, track(img, TrackerSettings.ALL_REGIONS.withMinBlobSize(6)).getNumBlobs(1));
  }

  @Test
  void largestFirstAndOnlyTheTrackedCount() {
    StringBuilder row = new StringBuilder();
    // Blobs of widths 1..12 separated by gaps, widest last.
    for (int w = 1; w <= 12; w++) {
      row.append("R".repeat(w)).append('.');
    }
    RgbImage img = Pictures.draw(row.toString());
    bank.setTrackedBlobs(1, 4);
    BlobFrame f = track(img, TrackerSettings.ALL_REGIONS);
    assertEquals(4, f.getNumBlobs(1));
    for (int n = 1; n <= 4; n++) {
      assertEquals(13 - n, f.getBlob(1, n).area());
    }
    bank.setTrackedBlobs(1, 10);
    assertEquals(10, track(img, TrackerSettings.ALL_REGIONS).getNumBlobs(1));
    assertEquals(3, track(img, TrackerSettings.ALL_REGIONS).getBlob(1, 10).area());
  }

  @Test
  void equalAreasKeepRasterOrder() {
    RgbImage img = Pictures.draw("..R.R", "R....");
    bank.setTrackedBlobs(1, 2);
    BlobFrame f = track(img, TrackerSettings.ALL_REGIONS);
    assertEquals(2, f.getBlob(1, 1).left());
    assertEquals(4, f.getBlob(1, 2).left());
  }

  @Test
  void untrainedChannelsReportNothing() {
    RgbImage img = Pictures.draw("RGB");
    BlobFrame f = track(img, TrackerSettings.ALL_REGIONS);
    assertEquals(3, f.totalBlobs());
    for (int c = 4; c <= 32; c++) {
      assertEquals(0, f.getNumBlobs(c));
    }
  }

  /** A checkerboard: one run and one 4-connected blob per interesting pixel. */
  @Test
  void pathologicalCheckerboardIsNeverTruncated() {
    int w = 640;
    int h = 480;
    int[] px = new int[w * h];
    for (int y = 0; y < h; y++) {
      for (int x = 0; x < w; x++) {
        px[y * w + x] = ((x + y) & 1) == 0 ? Pictures.RED : 0;
      }
    }
    RgbImage img = new RgbImage(w, h, px);
    BlobFrame f = track(img, TrackerSettings.ALL_REGIONS);
    assertEquals(w * h / 2, tracker.runs().count());
    assertEquals(10, f.getNumBlobs(1));
    assertEquals(1, f.getBlob(1, 10).area());
    ChannelComponents all = new ChannelComponents();
    tracker.components(px, w, h, bank.tables(), 1, all, null);
    assertEquals(w * h / 2, all.count());
    assertEquals(0, track(img, TrackerSettings.DEFAULT).getNumBlobs(1));
  }

  @Test
  void noiseFramesReuseTheGrownBuffers() {
    RgbImage noise = Pictures.noise(320, 240, 9);
    LookupTables t = bank.tables();
    tracker.track(noise.pixels(), 320, 240, t, TrackerSettings.ALL_REGIONS, frame);
    int capacity = tracker.runs().capacity();
    assertTrue(tracker.runs().count() > 20_000, "noise makes many runs");
    assertTrue(capacity >= tracker.runs().count());
    for (int i = 0; i < 3; i++) {
      tracker.track(noise.pixels(), 320, 240, t, TrackerSettings.ALL_REGIONS, frame);
    }
    assertEquals(capacity, tracker.runs().capacity(), "no growth once large enough");
  }

  @Test
  void densityMergeJoinsCloseFragmentsOnly() {
    RgbImage img =
        Pictures.draw(
            "RRRR.RRRR..........",
            "RRRR.RRRR..........",
            "RRRR.RRRR.........R",
            "...................");
    BlobFrame plain = track(img, TrackerSettings.ALL_REGIONS);
    assertEquals(3, plain.getNumBlobs(1));
    BlobFrame merged = track(img, TrackerSettings.ALL_REGIONS.withDensityMerge(1, 0.5));
    assertEquals(2, merged.getNumBlobs(1));
    Blob b = merged.getBlob(1, 1);
    assertEquals(24, b.area());
    assertEquals(0, b.left());
    assertEquals(8, b.right());
    assertEquals(4.0, b.xCentroid());
    assertEquals(1, merged.getBlob(1, 2).area());
    // Too sparse: the 1-pixel blob would make a box of density (24+1)/(19*3) < 0.5.
    assertEquals(
        2, track(img, TrackerSettings.ALL_REGIONS.withDensityMerge(100, 0.5)).getNumBlobs(1));
    // Gap too large.
    assertEquals(
        3, track(img, TrackerSettings.ALL_REGIONS.withDensityMerge(0, 0.5)).getNumBlobs(1));
  }

  @Test
  void labelsMatchComponents() {
    RgbImage img = Pictures.draw("RR.R", "...R", "RRRR");
    int[] labels = new int[12];
    ChannelComponents c = new ChannelComponents();
    tracker.components(img.pixels(), 4, 3, bank.tables(), 1, c, labels);
    assertEquals(2, c.count());
    assertEquals(
        java.util.List.of(1, 1, 0, 2, 0, 0, 0, 2, 2, 2, 2, 2),
        java.util.Arrays.stream(labels).boxed().toList());
    assertEquals(2, c.area(0));
    assertEquals(6, c.area(1));
    assertEquals(0.5, c.xCentroid(0));
  }
}
