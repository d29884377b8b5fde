package org.jaria.apps.eztrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.color.ColorPlane;
import org.jaria.acts.color.PlaneLimits;
import org.jaria.acts.color.Trainer;
import org.jaria.acts.config.ActsConfig;
import org.jaria.acts.image.RgbImage;
import org.jaria.acts.image.TestScene;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class EzTrainSessionTest {

  @TempDir Path dir;

  private EzTrainSession session() {
    EzTrainSession s = new EzTrainSession(new ChannelBank(), 160, 120, dir);
    s.setFrame(TestScene.load());
    return s;
  }

  @Test
  void framesAreScaledToTheWorkingSize() {
    EzTrainSession s = session();
    assertEquals(160, s.frame().width());
    assertEquals(120, s.frame().height());
    assertTrue(s.frame().samePixels(TestScene.load().scaled(160, 120)));
  }

  @Test
  void trainingDistinctColoursEqualsTrainingEveryPixel() {
    EzTrainSession s = session();
    TestScene.Box b = TestScene.BOOK.scaled(160, 120);
    s.trainRect(true, b.x0(), b.y0(), b.x1(), b.y1());
    ChannelBank reference = new ChannelBank();
    new Trainer(reference).addRect(s.frame(), b.x0(), b.y0(), b.x1(), b.y1());
    assertTrue(s.bank().copyOf(1).contentEquals(reference.copyOf(1)));
    assertEquals(1, s.unsavedMask());
  }

  @Test
  void distinctColoursOfARectangle() {
    RgbImage img = new RgbImage(3, 2, new int[] {5, 1, 5, 9, 1, 5});
    RgbImage c = EzTrainSession.distinctColors(img, 0, 0, 2, 1);
    assertEquals(3, c.width());
    assertEquals(List.of(1, 5, 9), List.of(c.get(0, 0), c.get(1, 0), c.get(2, 0)));
  }

  @Test
  void removeUndoClearAndStrokes() {
    EzTrainSession s = session();
    s.trainRect(true, 30, 67, 70, 75);
    s.trainRect(false, 30, 67, 70, 75);
    assertTrue(s.bank().copyOf(1).isEmpty());
    assertTrue(s.undo());
    assertFalse(s.bank().copyOf(1).isEmpty());
    s.clearTraining();
    assertTrue(s.bank().copyOf(1).isEmpty());
    s.setBrushSize(3);
    s.stroke(true, List.of(new int[] {50, 70}, new int[] {51, 70}, new int[] {52, 70}));
    assertFalse(s.bank().copyOf(1).isEmpty());
    assertTrue(s.undo(), "a whole stroke is one undo step");
    assertTrue(s.bank().copyOf(1).isEmpty());
    // Outside the image: nothing happens.
    s.trainRect(true, 500, 500, 600, 600);
    assertTrue(s.bank().copyOf(1).isEmpty());
  }

  @Test
  void manualPlaneOperationsAndChannelSelection() {
    EzTrainSession s = session();
    s.selectChannel(5);
    assertEquals(5, s.channel());
    s.fillPlane(ColorPlane.RG);
    assertEquals(256 * 256, s.bank().copyOf(5).trainedCells(ColorPlane.RG));
    s.setLimits(ColorPlane.RG, PlaneLimits.NONE.withBright(0, 100));
    assertEquals(100, s.bank().copyOf(5).getLimits(ColorPlane.RG).highBright());
    s.clearPlane(ColorPlane.RG);
    assertEquals(0, s.bank().copyOf(5).trainedCells(ColorPlane.RG));
    assertEquals(1 << 4, s.unsavedMask());
    assertTrue(s.bank().copyOf(1).isEmpty());
    assertTrue(s.pick(500, 0).contains("outside"));
    assertTrue(s.pick(0, 0).matches("\\(0, 0\\): R \\d+ G \\d+ B \\d+"));
  }

  @Test
  void channelFilesAndRuntimeConfigRoundTrip() throws IOException {
    EzTrainSession s = session();
    s.trainRect(true, 30, 67, 70, 75);
    s.setTrackedBlobs(2);
    Files.createDirectories(dir.resolve("luts"));
    s.saveChannel(dir.resolve("luts/red.lut"));
    assertEquals(0, s.unsavedMask());
    assertEquals("luts/red.lut", s.bank().getFileName(1).replace('\\', '/'));
    Path cfg = dir.resolve("actsconfig");
    ActsConfig written = s.saveConfig(cfg, 5, 5001);
    assertEquals(1, written.channels().size());
    assertEquals("luts/red.lut", written.channels().get(0).file().replace('\\', '/'));

    EzTrainSession fresh = new EzTrainSession(new ChannelBank(), 160, 120, dir);
    ActsConfig read = fresh.loadConfig(cfg);
    assertEquals(160, read.width());
    assertTrue(fresh.bank().copyOf(1).contentEquals(s.bank().copyOf(1)));
    assertEquals(2, fresh.bank().getTrackedBlobs(1));

    fresh.selectChannel(2);
    fresh.loadChannel(dir.resolve("luts/red.lut"));
    assertTrue(fresh.bank().copyOf(2).contentEquals(s.bank().copyOf(1)));
  }

  @Test
  void damagedChannelFileIsRefusedWithItsName() throws IOException {
    EzTrainSession s = session();
    Path bad = dir.resolve("bad.lut");
    Files.writeString(bad, "not a channel");
    IOException e = assertThrows(IOException.class, () -> s.loadChannel(bad));
    assertTrue(e.getMessage().contains("bad.lut"), e::getMessage);
    assertTrue(s.bank().copyOf(1).isEmpty());
  }
}
