package org.jaria.acts.color;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.jaria.acts.image.RgbImage;
import org.junit.jupiter.api.Test;

class ChannelTest {

  @Test
  void addColorSetsTheNeighbourhoodSquareInEveryPlane() {
    Channel c = new Channel(8);
    c.addColor(RgbImage.pack(100, 50, 20), 2);
    // RG plane: red 98..102 x green 48..52.
    assertEquals(25, c.trainedCells(ColorPlane.RG));
    assertTrue(c.isTrained(ColorPlane.RG, 98, 48));
    assertTrue(c.isTrained(ColorPlane.RG, 102, 52));
    assertFalse(c.isTrained(ColorPlane.RG, 103, 50));
    // BG plane: blue 18..22 x green 48..52; RB plane: red 98..102 x blue 18..22.
    assertTrue(c.isTrained(ColorPlane.BG, 18, 52));
    assertTrue(c.isTrained(ColorPlane.RB, 102, 18));
    assertFalse(c.isTrained(ColorPlane.RB, 102, 23));
    assertTrue(c.classifies(RgbImage.pack(101, 49, 22)));
    assertFalse(c.classifies(RgbImage.pack(101, 49, 23)));
  }

  @Test
  void neighbourhoodIsClippedAtTheEdgesOfThePlane() {
    Channel c = new Channel(8);
    c.addColor(RgbImage.pack(0, 255, 1), 3);
    assertEquals(4 * 4, c.trainedCells(ColorPlane.RG)); // red 0..3, green 252..255
    assertEquals(5 * 4, c.trainedCells(ColorPlane.BG)); // blue 0..4, green 252..255
  }

  @Test
  void removeColorClearsTheSameSquare() {
    Channel c = new Channel(8);
    c.addRgbBox(90, 110, 40, 60, 10, 30);
    assertTrue(c.classifies(RgbImage.pack(100, 50, 20)));
    c.removeColor(RgbImage.pack(100, 50, 20), 1);
    assertFalse(c.classifies(RgbImage.pack(100, 50, 20)));
    assertFalse(c.classifies(RgbImage.pack(101, 51, 21)));
    assertTrue(c.classifies(RgbImage.pack(103, 53, 23)), "outside the removed squares");
    // Removal clears a square in every plane, so colours sharing a projection go too (as in ACTS).
    assertFalse(c.classifies(RgbImage.pack(103, 50, 20)), "its BG projection was removed");
  }

  @Test
  void anRgbBoxClassifiesExactlyTheBoxAtFullResolution() {
    Channel c = new Channel(8);
    c.addRgbBox(10, 20, 30, 40, 50, 60);
    SplittableRandom r = new SplittableRandom(1);
    for (int i = 0; i < 20_000; i++) {
      int red = r.nextInt(0, 70);
      int g = r.nextInt(0, 70);
      int b = r.nextInt(0, 70);
      boolean inside = red >= 10 && red <= 20 && g >= 30 && g <= 40 && b >= 50 && b <= 60;
      assertEquals(inside, c.classifies(RgbImage.pack(red, g, b)), red + "," + g + "," + b);
    }
  }

  @Test
  void coarseCellsRoundABoxOutwardsToCellEdges() {
    Channel c = new Channel(6); // 4 colour values per cell
    c.addRgbBox(10, 20, 30, 40, 50, 60);
    assertTrue(c.classifies(RgbImage.pack(8, 28, 48)));
    assertTrue(c.classifies(RgbImage.pack(23, 43, 63)));
    assertFalse(c.classifies(RgbImage.pack(24, 40, 60)));
    assertFalse(c.classifies(RgbImage.pack(7, 40, 60)));
  }

  @Test
  void fillAndClearPlane() {
    Channel c = new Channel(7);
    for (ColorPlane p : ColorPlane.all()) {
      c.fillPlane(p);
    }
    assertEquals(128 * 128, c.trainedCells(ColorPlane.BG));
    assertTrue(c.classifies(0x123456));
    c.clearPlane(ColorPlane.BG);
    assertFalse(c.classifies(0x123456));
    assertFalse(c.isEmpty());
    c.clear();
    assertTrue(c.isEmpty());
  }

  @Test
  void brightLimitsRemoveTheDarkAndBrightCornersWithoutErasingTraining() {
    Channel c = new Channel(8);
    for (ColorPlane p : ColorPlane.all()) {
      c.fillPlane(p);
    }
    c.setLimits(ColorPlane.RG, PlaneLimits.NONE.withBright(100, 400));
    assertFalse(c.classifies(RgbImage.pack(40, 40, 128)), "r+g = 80 < low bright");
    assertFalse(c.classifies(RgbImage.pack(210, 200, 128)), "r+g = 410 > high bright");
    assertTrue(c.classifies(RgbImage.pack(150, 100, 0)));
    assertTrue(c.isTrained(ColorPlane.RG, 40, 40), "limits only mask the training");
    c.resetLimits();
    assertTrue(c.classifies(RgbImage.pack(40, 40, 128)));
  }

  @Test
  void colourLimitsSweepFromEachAxis() {
    Channel c = new Channel(8);
    for (ColorPlane p : ColorPlane.all()) {
      c.fillPlane(p);
    }
    // RG plane: remove 30 degrees next to the red axis (strongly red colours).
    c.setLimits(ColorPlane.RG, PlaneLimits.NONE.withColor(30, 0));
    assertFalse(c.classifies(RgbImage.pack(200, 20, 100)), "angle ~5.7 degrees");
    assertTrue(c.classifies(RgbImage.pack(100, 100, 100)), "45 degrees");
    assertTrue(c.classifies(RgbImage.pack(10, 200, 100)), "near the green axis");
    // And 30 degrees next to the green axis.
    c.setLimits(ColorPlane.RG, PlaneLimits.NONE.withColor(0, 30));
    assertTrue(c.classifies(RgbImage.pack(200, 20, 100)));
    assertFalse(c.classifies(RgbImage.pack(10, 200, 100)));
  }

  @Test
  void limitsAreValidated() {
    assertThrows(IllegalArgumentException.class, () -> new PlaneLimits(91, 0, 0, 510));
    assertThrows(IllegalArgumentException.class, () -> new PlaneLimits(0, 0, -1, 510));
    assertThrows(IllegalArgumentException.class, () -> new PlaneLimits(0, 0, 0, 511));
    assertThrows(IllegalArgumentException.class, () -> new Channel(9));
    assertThrows(IllegalArgumentException.class, () -> new Channel(8).addRgbBox(5, 4, 0, 1, 0, 1));
  }

  @Test
  void copyAndContentEquals() {
    Channel c = new Channel(8);
    c.addColor(0x804020, 3);
    c.setLimits(ColorPlane.RB, new PlaneLimits(5, 6, 7, 300));
    Channel d = c.copy();
    assertTrue(d.contentEquals(c));
    d.addColor(0x000000, 0);
    assertFalse(d.contentEquals(c));
    assertThrows(IllegalArgumentException.class, () -> new Channel(6).copyFrom(c));
  }

  @Test
  void resamplingCoarserKeepsEveryTrainedColourAndFinerKeepsTheCells() {
    Channel fine = new Channel(8);
    fine.addColor(RgbImage.pack(100, 50, 20), 0);
    Channel coarse = fine.resampled(6);
    assertEquals(1, coarse.trainedCells(ColorPlane.RG));
    assertTrue(coarse.classifies(RgbImage.pack(100, 50, 20)));
    assertTrue(coarse.classifies(RgbImage.pack(103, 49, 23)), "same 4x4 cell");
    Channel back = coarse.resampled(8);
    assertEquals(16, back.trainedCells(ColorPlane.RG));
    assertTrue(back.classifies(RgbImage.pack(103, 49, 23)));
    assertTrue(back.resampled(6).contentEquals(coarse));
  }
}
