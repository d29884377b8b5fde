package org.jaria.acts.color;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.acts.blob.BlobFrame;
import org.jaria.acts.blob.BlobTracker;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.image.RgbImage;
import org.jaria.acts.image.TestScene;
import org.jaria.acts.testing.Pictures;
import org.junit.jupiter.api.Test;

class TrainerTest {

  private final ChannelBank bank = new ChannelBank();
  private final Trainer trainer = new Trainer(bank);

  /** The thesis's tutorial (§5.3.12): channel 1, two blobs, Add on the book and the cup. */
  @Test
  void tutorialTrainsChannelOneOnTheRedBookAndCup() {
    RgbImage scene = TestScene.render(160, 120);
    trainer.setChannel(1);
    bank.setTrackedBlobs(1, 2);
    TestScene.Box book = TestScene.BOOK.scaled(160, 120);
    TestScene.Box cup = TestScene.CUP.scaled(160, 120);
    trainer.addRect(scene, book.x0(), book.y0(), book.x1(), book.y1());
    trainer.addRect(scene, cup.x0(), cup.y0(), cup.x1(), cup.y1());

    BlobFrame f = new BlobFrame();
    new BlobTracker().track(scene.pixels(), 160, 120, bank.tables(), TrackerSettings.DEFAULT, f);
    assertEquals(2, f.getNumBlobs(1));
    var biggest = f.getBlob(1, 1);
    var second = f.getBlob(1, 2);
    TestScene.Box bookExtent = TestScene.BOOK_EXTENT.scaled(160, 120);
    TestScene.Box cupExtent = TestScene.CUP_EXTENT.scaled(160, 120);
    assertTrue(bookExtent.contains(biggest.xcg(), biggest.ycg()), "book first: " + biggest);
    assertTrue(cupExtent.contains(second.xcg(), second.ycg()), "cup second: " + second);
    assertTrue(biggest.area() > second.area());
    // Other channels are untouched.
    assertEquals(0, f.getNumBlobs(2));
  }

  @Test
  void removeTakesColoursOutAndUndoPutsThemBack() {
    RgbImage img = Pictures.draw("RRRR", "RRRR");
    trainer.addRect(img, 0, 0, 3, 1);
    assertEquals(1, bank.tables().classify(Pictures.RED));
    trainer.removeRect(img, 1, 1, 1, 1);
    assertEquals(0, bank.tables().classify(Pictures.RED));
    assertTrue(trainer.undo());
    assertEquals(1, bank.tables().classify(Pictures.RED));
    assertTrue(trainer.undo());
    assertEquals(0, bank.tables().classify(Pictures.RED));
    assertFalse(trainer.undo(), "nothing left to undo");
  }

  @Test
  void neighbourhoodAddsSimilarColoursToo() {
    RgbImage img = Pictures.draw("R");
    trainer.setNeighbourhood(4);
    trainer.addRect(img, 0, 0, 0, 0);
    assertEquals(1, bank.tables().classify(RgbImage.pack(251, 3, 4)));
    assertEquals(0, bank.tables().classify(RgbImage.pack(250, 0, 0)));
    trainer.clearTraining();
    trainer.setNeighbourhood(0);
    trainer.addRect(img, 0, 0, 0, 0);
    assertEquals(0, bank.tables().classify(RgbImage.pack(254, 0, 0)));
  }

  @Test
  void drawAndEraseUseTheBrushSquare() {
    RgbImage img = new RgbImage(9, 9);
    for (int y = 0; y < 9; y++) {
      for (int x = 0; x < 9; x++) {
        img.set(x, y, RgbImage.pack(10 * x, 10 * y, 0));
      }
    }
    trainer.setBrushSize(3);
    trainer.draw(img, 4, 4);
    LookupTables t = bank.tables();
    assertEquals(1, t.classify(RgbImage.pack(30, 30, 0)), "brush covers (3..5, 3..5)");
    assertEquals(1, t.classify(RgbImage.pack(50, 50, 0)));
    assertEquals(0, t.classify(RgbImage.pack(60, 50, 0)));
    assertEquals(0, t.classify(RgbImage.pack(31, 30, 0)), "draw adds exact colours only");
    trainer.setBrushSize(1);
    trainer.erase(img, 5, 5);
    assertEquals(0, bank.tables().classify(RgbImage.pack(50, 50, 0)));
    assertEquals(1, bank.tables().classify(RgbImage.pack(40, 40, 0)));
    trainer.setBrushSize(9);
    trainer.draw(img, 0, 0); // clipped at the image corner
    assertEquals(1, bank.tables().classify(RgbImage.pack(0, 40, 0)));
    assertEquals(0, bank.tables().classify(RgbImage.pack(50, 0, 0)), "brush covers -4..4");
    assertThrows(IllegalArgumentException.class, () -> trainer.setBrushSize(10));
    assertThrows(IllegalArgumentException.class, () -> trainer.setBrushSize(0));
  }

  @Test
  void pickReturnsThePixelAndChangesNothing() {
    RgbImage img = Pictures.draw("..", ".Y");
    long v = bank.version();
    assertEquals(Pictures.YELLOW, trainer.pick(img, 1, 1));
    assertEquals("R 255 G 255 B 0", Trainer.describe(trainer.pick(img, 1, 1)));
    assertEquals(v, bank.version());
    assertEquals(0, trainer.undoDepth());
  }

  @Test
  void undoIsPerChannelWithSeveralLevels() {
    RgbImage img = Pictures.draw("RGB");
    trainer.setNeighbourhood(0);
    trainer.setChannel(1);
    trainer.addRect(img, 0, 0, 0, 0);
    trainer.addRect(img, 1, 0, 1, 0);
    trainer.setChannel(2);
    trainer.addRect(img, 2, 0, 2, 0);
    assertEquals(1, trainer.undoDepth());
    trainer.setChannel(1);
    assertEquals(2, trainer.undoDepth());
    assertTrue(trainer.undo()); // channel 1 loses green, channel 2 keeps blue
    LookupTables t = bank.tables();
    assertEquals(1, t.classify(Pictures.RED));
    assertEquals(0, t.classify(Pictures.GREEN));
    assertEquals(2, t.classify(Pictures.BLUE));
  }

  @Test
  void undoLevelsAreBounded() {
    RgbImage img = Pictures.draw("R");
    trainer.setUndoLevels(3);
    for (int i = 0; i < 10; i++) {
      trainer.addRect(img, 0, 0, 0, 0);
    }
    assertEquals(3, trainer.undoDepth());
  }

  @Test
  void aGroupIsUndoneAtOnce() {
    RgbImage img = Pictures.draw("RGB");
    trainer.setNeighbourhood(0);
    trainer.beginGroup();
    trainer.draw(img, 0, 0);
    trainer.draw(img, 1, 0);
    trainer.draw(img, 2, 0);
    trainer.endGroup();
    assertEquals(1, trainer.undoDepth());
    trainer.undo();
    assertEquals(0, bank.tables().classify(Pictures.BLUE));
    assertEquals(0, bank.tables().classify(Pictures.RED));
    assertThrows(IllegalStateException.class, trainer::endGroup);
  }

  @Test
  void manualModeFillPlaneAndLimits() {
    for (ColorPlane p : ColorPlane.all()) {
      trainer.fillPlane(p);
    }
    assertEquals(1, bank.tables().classify(0x808080), "every colour once all planes are full");
    trainer.setBrightLimits(ColorPlane.RG, 0, 200);
    assertEquals(0, bank.tables().classify(0x808080), "r+g = 256 > 200");
    assertEquals(new PlaneLimits(0, 0, 0, 200), trainer.getLimits(ColorPlane.RG));
    trainer.setColorLimits(ColorPlane.BG, 10, 20);
    assertEquals(new PlaneLimits(10, 20, 0, 510), trainer.getLimits(ColorPlane.BG));
    trainer.resetLimits();
    assertEquals(1, bank.tables().classify(0x808080));
    trainer.clearPlane(ColorPlane.RB);
    assertEquals(0, bank.tables().classify(0x808080));
    trainer.undo();
    assertEquals(1, bank.tables().classify(0x808080), "Clear Plane is undoable");
  }

  @Test
  void rectanglesOutsideTheImageDoNothing() {
    RgbImage img = Pictures.draw("RR");
    trainer.addRect(img, 5, 5, 9, 9);
    assertEquals(0, trainer.undoDepth());
    trainer.addRect(img, -3, -3, 0, 0); // clipped to the corner pixel
    assertEquals(1, bank.tables().classify(Pictures.RED));
  }
}
