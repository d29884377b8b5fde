package org.jaria.acts.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.jaria.acts.ActsFormatException;
import org.jaria.acts.color.Channel;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.color.ChannelLutFile;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ActsConfigTest {

  @TempDir Path dir;

  @Test
  void parsesTheDocumentedFormat() throws ActsFormatException {
    ActsConfig c =
        ActsConfig.parse(
            """
            ; comment
            Width 320
            height 240 # trailing
            MinBlobSize 3
            Port 6000
            Channel 1 channel1.lut 2
            CHANNEL 12 "green ball.lut" 10
            """,
            "cfg");
    assertEquals(320, c.width());
    assertEquals(240, c.height());
    assertEquals(3, c.minBlobSize());
    assertEquals(6000, c.port());
    assertEquals(
        List.of(
            new ActsConfig.ChannelEntry(1, "channel1.lut", 2),
            new ActsConfig.ChannelEntry(12, "green ball.lut", 10)),
        c.channels());
    assertEquals(c, ActsConfig.parse(c.format(), "again"));
  }

  @Test
  void emptyFileGivesTheDefaults() throws ActsFormatException {
    assertEquals(ActsConfig.DEFAULT, ActsConfig.parse("", "empty"));
  }

  @Test
  void errorsNameTheFileAndLine() {
    assertError("Width 160\nWidht 120\n", "cfg:2: unknown keyword 'Widht'");
    assertError("Port seventy\n", "cfg:1: Port needs a whole number");
    assertError("Width 5000\n", "cfg:1: Width must be 1..4095");
    assertError("\n\nChannel 33 a.lut 1\n", "cfg:3: channel must be a whole number 1..32");
    assertError("Channel 1 a.lut 11\n", "blobs must be a whole number 1..10");
    assertError("Channel 1 a.lut\n", "expected 'Channel");
    assertError("Channel 1 a.lut 1\nChannel 1 b.lut 1\n", "cfg:2: channel 1 is listed twice");
    assertError("Channel 1 \"a.lut 1\n", "no closing");
    assertError("Width 1 2\n", "takes one value");
  }

  private static void assertError(String text, String expected) {
    ActsFormatException e =
        assertThrows(ActsFormatException.class, () -> ActsConfig.parse(text, "cfg"));
    assertTrue(e.getMessage().contains(expected), e.getMessage());
  }

  @Test
  void binaryFileIsRejected() throws IOException {
    Path f = dir.resolve("cfg");
    Files.write(f, new byte[] {(byte) 0xC3, 0x28, 1, 2});
    ActsFormatException e = assertThrows(ActsFormatException.class, () -> ActsConfig.read(f));
    assertTrue(e.getMessage().contains("not a text file"), e.getMessage());
  }

  @Test
  void appliesChannelsRelativeToTheConfigFolder() throws IOException {
    Channel red = new Channel(8);
    red.addRgbBox(128, 255, 0, 80, 0, 80);
    Path sub = Files.createDirectory(dir.resolve("luts"));
    ChannelLutFile.write(red, sub.resolve("red.lut"));
    ActsConfig cfg =
        new ActsConfig(
            160, 120, 5, 5002, List.of(new ActsConfig.ChannelEntry(4, "luts/red.lut", 2)));
    cfg.write(dir.resolve("actsconfig"));
    ActsConfig back = ActsConfig.read(dir.resolve("actsconfig"));
    assertEquals(cfg, back);
    ChannelBank bank = new ChannelBank();
    back.applyTo(bank, dir);
    assertEquals(1 << 3, bank.tables().classify(0xFF0000));
    assertEquals(2, bank.getTrackedBlobs(4));
    assertEquals("luts/red.lut", bank.getFileName(4));
    assertEquals(
        List.of(new ActsConfig.ChannelEntry(4, "luts/red.lut", 2)),
        ActsConfig.of(bank, 160, 120, 5, 5001).channels());
  }

  @Test
  void aDamagedChannelFileLeavesTheBankUntouched() throws IOException {
    Channel red = new Channel(8);
    red.addRgbBox(128, 255, 0, 80, 0, 80);
    ChannelLutFile.write(red, dir.resolve("good.lut"));
    Files.writeString(dir.resolve("bad.lut"), "JARIA-ACTS-LUT 1\ncells 256\n");
    ChannelBank bank = new ChannelBank();
    bank.replace(9, red);
    ActsConfig cfg = ActsConfig.parse("Channel 1 good.lut 3\nChannel 2 bad.lut 3\n", "cfg");
    ActsFormatException e = assertThrows(ActsFormatException.class, () -> cfg.applyTo(bank, dir));
    assertTrue(e.getMessage().contains("bad.lut"), e.getMessage());
    assertEquals(1 << 8, bank.tables().classify(0xFF0000), "bank unchanged");
    ActsConfig missing = ActsConfig.parse("Channel 1 nothere.lut 3\n", "cfg");
    IOException m = assertThrows(IOException.class, () -> missing.applyTo(bank, dir));
    assertTrue(m.getMessage().contains("does not exist"), m.getMessage());
  }
}
