package org.jaria.laser;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.DropReason;
import org.junit.jupiter.api.Test;

/** LMS telegram framing and CRC against byte strings published for the LMS-200. */
class LmsTelegramTest {

  private static byte[] hex(String s) {
    return HexFormat.ofDelimiter(" ").parseHex(s.toLowerCase(java.util.Locale.ROOT));
  }

  @Test
  void modeChangesEncodeAsTheManualPrintsThem() {
    assertArrayEquals(
        hex("02 00 02 00 20 24 34 08"),
        LmsSettings.modeChange(LmsCommands.MODE_CONTINUOUS).encode());
    assertArrayEquals(
        hex("02 00 02 00 20 25 35 08"), LmsSettings.modeChange(LmsCommands.MODE_STOP).encode());
    assertArrayEquals(hex("02 00 02 00 20 40 50 08"), LmsSettings.baudChange(38400).encode());
    assertArrayEquals(hex("02 00 02 00 20 41 51 08"), LmsSettings.baudChange(19200).encode());
    assertArrayEquals(hex("02 00 02 00 20 42 52 08"), LmsSettings.baudChange(9600).encode());
  }

  @Test
  void variantAndInstallModeEncodeAsPublished() {
    assertArrayEquals(
        hex("02 00 05 00 3B B4 00 64 00 97 49"),
        new LmsSettings(180, 1, "1mm", 1, 38400).variant().encode());
    assertArrayEquals(
        hex("02 00 0A 00 20 00 53 49 43 4B 5F 4C 4D 53 BE C5"),
        LmsSettings.modeChange(
                LmsCommands.MODE_INSTALL, "SICK_LMS".getBytes(StandardCharsets.US_ASCII))
            .encode());
  }

  @Test
  void configurationBlockCarriesModeAndUnits() {
    LmsTelegram t = new LmsSettings(180, 0.5, "1cm", 3, 38400).configuration();
    assertEquals(LmsCommands.CONFIGURE, t.command());
    assertEquals(33, t.dataLength());
    assertEquals(70, t.u16(2), "peak threshold");
    assertEquals(1, t.u8(5), "3 reflector bits = measuring mode 1");
    assertEquals(0, t.u8(6), "cm = unit byte 0");
    assertEquals(3, LmsSettings.reflectorBitsOfMode(t.u8(5)));
    assertEquals("1cm", LmsSettings.unitsOfByte(t.u8(6)));
  }

  @Test
  void receiverSkipsAcksAndNoiseAndResyncsAfterALostByte() {
    DropCounters drops = new DropCounters("test");
    LmsReceiver rx = new LmsReceiver(true, drops);
    List<LmsTelegram> got = new ArrayList<>();
    byte[] a = LmsTelegram.fromLaser(LmsCommands.MODE_ANSWER, (byte) 0, (byte) 0x10).encode();
    byte[] damaged = a.clone();
    damaged[5] ^= 0x01;
    byte[] lost = new byte[a.length - 1];
    System.arraycopy(a, 0, lost, 0, 4);
    System.arraycopy(a, 5, lost, 4, a.length - 5);
    byte[] stream = concat(new byte[] {6, 0x55}, damaged, lost, new byte[] {6}, a, a);
    // Fed one byte at a time: framing must not depend on how reads cut the stream.
    for (byte b : stream) {
      rx.feed(new byte[] {b}, 0, 1, got::add);
    }
    assertEquals(2, got.size(), "only the two intact telegrams");
    assertEquals(LmsCommands.MODE_ANSWER, got.get(0).command());
    assertArrayEquals(new byte[] {0, 0x10}, got.get(0).data());
    assertEquals(2, rx.getAckCount());
    assertEquals(2, drops.get(DropReason.BAD_CHECKSUM), "the damaged one and the short one");
  }

  @Test
  void receiverRejectsAnAbsurdLengthWithoutWaitingForIt() {
    DropCounters drops = new DropCounters("test");
    LmsReceiver rx = new LmsReceiver(true, drops);
    List<LmsTelegram> got = new ArrayList<>();
    byte[] a = LmsTelegram.fromLaser(LmsCommands.SCAN, new byte[7]).encode();
    rx.feed(
        concat(new byte[] {2, (byte) 0x80, (byte) 0xff, (byte) 0xff}, a),
        0,
        4 + a.length,
        got::add);
    assertEquals(1, got.size());
    assertEquals(1, drops.get(DropReason.BAD_LENGTH));
  }

  @Test
  void scanDataRoundTripsWithUnitsAndReflectorBits() {
    int[] raw = {0, 1234, 8191, 20};
    int[] refl = {0, 7, 4, 2};
    LmsTelegram t = LmsScanData.encode(raw, refl, 10, 3, 0x10);
    assertEquals(0x4004 & 0x3ff, t.u16(0) & 0x3ff);
    assertEquals(0, t.u16(0) >>> 14, "cm units are 00");
    LmsScanData d = LmsScanData.decode(t, 3);
    assertArrayEquals(new int[] {0, 12340, 81910, 200}, d.distancesMm());
    assertArrayEquals(refl, d.reflectance());
    assertEquals(0x10, d.status());
  }

  @Test
  void scanDataWithOneReflectorBitInMillimetres() {
    // 2 readings, mm units (bit 14): 0x4002; 1000 mm; 500 mm with the reflector bit set.
    LmsTelegram t = LmsTelegram.fromLaser(0xb0, hex("02 40 E8 03 F4 81 10"));
    LmsScanData d = LmsScanData.decode(t, 1);
    assertArrayEquals(new int[] {1000, 500}, d.distancesMm());
    assertArrayEquals(new int[] {0, 4}, d.reflectance());
    assertEquals(1, d.unitMm());
  }

  @Test
  void scanDataWhoseCountDisagreesWithItsLengthIsRefused() {
    LmsTelegram t = LmsTelegram.fromLaser(0xb0, hex("05 40 E8 03 10"));
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> LmsScanData.decode(t, 1));
    assertEquals("scan telegram of 5 values has 5 data bytes", e.getMessage());
  }

  @Test
  void settingsRefuseWhatTheLaserCannotDo() {
    assertThrows(IllegalArgumentException.class, () -> new LmsSettings(90, 1, "1mm", 1, 38400));
    assertThrows(IllegalArgumentException.class, () -> new LmsSettings(180, 0.25, "1mm", 1, 38400));
    assertThrows(IllegalArgumentException.class, () -> new LmsSettings(180, 1, "2mm", 1, 38400));
    assertThrows(IllegalArgumentException.class, () -> new LmsSettings(180, 1, "1mm", 1, 57600));
    assertEquals(361, new LmsSettings(180, 0.5, "1mm", 1, 38400).readingCount());
    assertEquals(401, new LmsSettings(100, 0.25, "1mm", 1, 38400).readingCount());
    assertEquals(8191, new LmsSettings(180, 1, "1mm", 3, 38400).maxRangeMm());
  }

  private static byte[] concat(byte[]... parts) {
    int n = 0;
    for (byte[] p : parts) {
      n += p.length;
    }
    byte[] out = new byte[n];
    int k = 0;
    for (byte[] p : parts) {
      System.arraycopy(p, 0, out, k, p.length);
      k += p.length;
    }
    return out;
  }
}
