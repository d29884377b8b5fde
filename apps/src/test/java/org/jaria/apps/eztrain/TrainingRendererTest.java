package org.jaria.apps.eztrain;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.jaria.acts.blob.BlobFrame;
import org.jaria.acts.blob.BlobTracker;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.color.Channel;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.color.ColorPlane;
import org.jaria.acts.color.LookupTables;
import org.jaria.acts.color.PlaneLimits;
import org.jaria.acts.image.RgbImage;
import org.junit.jupiter.api.Test;

class TrainingRendererTest {

  private static final int RED = 0xC81E1E;
  private static final int GREY = 0x808080;

  /** A 20x10 grey image with a red 6x4 patch at (5, 3). */
  private static RgbImage image() {
    RgbImage img = new RgbImage(20, 10);
    for (int y = 0; y < 10; y++) {
      for (int x = 0; x < 20; x++) {
        img.set(x, y, x >= 5 && x <= 10 && y >= 3 && y <= 6 ? RED : GREY);
      }
    }
    return img;
  }

  private static LookupTables redChannel(ChannelBank bank) {
    bank.edit(
        1,
        c -> {
          c.addColor(RED, 2);
          return null;
        });
    return bank.tables();
  }

  @Test
  void everyViewMode() {
    RgbImage img = image();
    LookupTables t = redChannel(new ChannelBank());
    int in = 4 * 20 + 7;
    int out = 0;
    int[] overlay = TrainingRenderer.render(img, t, 1, null, ViewMode.OVERLAY, 0x0000FF);
    assertEquals(0xFF0000FF, overlay[in]);
    assertEquals(0xFF000000 | GREY, overlay[out]);
    int[] thresh = TrainingRenderer.render(img, t, 1, null, ViewMode.THRESH, 0x0000FF);
    assertEquals(0xFFFFFFFF, thresh[in]);
    assertEquals(0xFF000000, thresh[out]);
    int[] raw = TrainingRenderer.render(img, t, 1, null, ViewMode.RAW, 0x0000FF);
    assertEquals(0xFF000000 | RED, raw[in]);
    int[] visible = TrainingRenderer.render(img, t, 1, null, ViewMode.VISIBLE, 0x0000FF);
    assertEquals(0xFF000000 | RED, visible[in]);
    assertEquals(0xFF000000, visible[out]);
    // Another channel sees nothing.
    assertEquals(0xFF000000, TrainingRenderer.render(img, t, 2, null, ViewMode.THRESH, 0)[in]);
  }

  @Test
  void threshBoxesBlobsInPurple() {
    RgbImage img = image();
    LookupTables t = redChannel(new ChannelBank());
    BlobFrame f = new BlobFrame();
    new BlobTracker().track(img.pixels(), 20, 10, t, TrackerSettings.ALL_REGIONS, f);
    assertEquals(1, f.getNumBlobs(1));
    int[] px = TrainingRenderer.render(img, t, 1, f, ViewMode.THRESH, 0);
    int purple = 0xFF000000 | TrainingRenderer.BLOB_PURPLE;
    assertEquals(purple, px[3 * 20 + 5], "top-left corner of the box");
    assertEquals(purple, px[6 * 20 + 10], "bottom-right corner");
    assertEquals(purple, px[f.getBlob(1, 1).ycg() * 20 + f.getBlob(1, 1).xcg()], "centroid");
    assertEquals(0xFFFFFFFF, px[4 * 20 + 6], "inside stays white");
  }

  @Test
  void planeImageShowsTrainedAllowedAndLimitedCells() {
    Channel c = new Channel(8);
    c.setCell(ColorPlane.RG, 200, 30, true);
    c.setCell(ColorPlane.RG, 250, 250, true);
    c.setLimits(ColorPlane.RG, PlaneLimits.NONE.withBright(0, 400));
    int[] px = TrainingRenderer.renderPlane(c, ColorPlane.RG);
    assertEquals(256 * 256, px.length);
    assertEquals(0xFFFFFFFF, px[(255 - 30) * 256 + 200], "trained and allowed: white");
    assertEquals(0xFF505050, px[(255 - 250) * 256 + 250], "too bright for the limits: grey");
    assertEquals(0xFF000000, px[(255 - 30) * 256 + 201], "untrained: black");
  }

  @Test
  void viewModesCycleAndParse() {
    assertEquals(ViewMode.THRESH, ViewMode.OVERLAY.next());
    assertEquals(ViewMode.OVERLAY, ViewMode.VISIBLE.next());
    assertEquals(ViewMode.RAW, ViewMode.parse("raw"));
    assertEquals(ViewMode.VISIBLE, ViewMode.parse("4"));
    assertEquals('2', ViewMode.THRESH.key());
  }
}
