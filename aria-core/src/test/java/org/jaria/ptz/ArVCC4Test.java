package org.jaria.ptz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Command frames against the Canon VC-C50i programmer's manual (same protocol as the VC-C4): the
 * frames and worked examples it prints, and ARIA's ArVCC4 for the commands ARIA sends.
 */
class ArVCC4Test {

  private final List<String> sent = new ArrayList<>();
  private final ArVCC4 camera = new ArVCC4(f -> sent.add(VCC4Packets.toHex(f)));

  @Test
  void framesFromTheManual() {
    // §12.11 Pedestal Initialize 1 and §16.2 frame (3).
    assertEquals("FF 30 30 00 58 30 EF", VCC4Packets.toHex(VCC4Packets.pedestalInit()));
    // §13.2 Camera ON.
    assertEquals("FF 30 30 00 A0 31 EF", VCC4Packets.toHex(VCC4Packets.power(true)));
    assertEquals("FF 30 30 00 A0 30 EF", VCC4Packets.toHex(VCC4Packets.power(false)));
    // §12.5 Pan/Tilt Stop.
    assertEquals("FF 30 30 00 53 30 EF", VCC4Packets.toHex(VCC4Packets.stopPanTilt()));
    // Pan/Tilt Angle Assignment example: pan right 90 degrees (+800 = 8320h), tilt lower 30
    // degrees (-267 = 7EF5h), sent as ASCII "8320" "7EF5".
    assertEquals(
        "FF 30 30 00 62 38 33 32 30 37 45 46 35 EF",
        VCC4Packets.toHex(VCC4Packets.panTilt(90, -30)));
    // §13.18 Zoom Position 2 Assignment example: 256 = 0100h = 30 31 30 30.
    assertEquals("FF 30 30 00 B3 30 31 30 30 EF", VCC4Packets.toHex(VCC4Packets.zoom(256)));
    // §13.55 Electronic zoom: 8x = 08h = 30 38.
    assertEquals("FF 30 30 00 B7 30 38 EF", VCC4Packets.toHex(VCC4Packets.digitalZoom(3)));
    assertEquals("FF 30 30 00 B7 30 31 EF", VCC4Packets.toHex(VCC4Packets.digitalZoom(0)));
    // §14.26 LED forced control, all LEDs off = 32h.
    assertEquals("FF 30 30 00 8E 32 EF", VCC4Packets.toHex(VCC4Packets.ledControl(2)));
  }

  @Test
  void framesAsAriaSendsThem() {
    assertEquals("FF 30 30 00 90 30 EF", VCC4Packets.toHex(VCC4Packets.hostControlMode()));
    assertEquals("FF 30 30 00 A2 30 EF", VCC4Packets.toHex(VCC4Packets.stopZoom()));
    // 90 deg/s = 800 units = 320h; 69 deg/s = 613 units = 265h.
    assertEquals("FF 30 30 00 50 33 32 30 EF", VCC4Packets.toHex(VCC4Packets.panSlew(90)));
    assertEquals("FF 30 30 00 51 32 36 35 EF", VCC4Packets.toHex(VCC4Packets.tiltSlew(69)));
    // Tilt range -30..88 deg: -267 -> 7EF5, 782 -> 830E.
    assertEquals(
        "FF 30 30 00 64 31 37 45 46 35 38 33 30 45 EF",
        VCC4Packets.toHex(VCC4Packets.tiltRange(-30, 88)));
    assertEquals("FF 30 30 00 63 EF", VCC4Packets.toHex(VCC4Packets.requestPanTilt()));
    assertEquals("FF 30 30 00 B4 30 EF", VCC4Packets.toHex(VCC4Packets.requestZoom()));
  }

  @Test
  void positionsRoundHalfAwayFromZero() {
    assertEquals(0x8000, VCC4Packets.units(0));
    assertEquals(0x8000 + 1, VCC4Packets.units(0.05625)); // exactly half a unit
    assertEquals(0x8000 - 1, VCC4Packets.units(-0.05625));
    assertEquals(0x8000 - 871, VCC4Packets.units(-98));
    assertEquals(
        "FF 30 30 00 62 38 30 30 30 38 30 30 30 EF", VCC4Packets.toHex(VCC4Packets.panTilt(0, 0)));
  }

  @Test
  void initSendsAriasStartUpSequence() {
    camera.init();
    assertEquals(
        List.of(
            "FF 30 30 00 A0 31 EF",
            "FF 30 30 00 90 30 EF",
            "FF 30 30 00 58 30 EF",
            "FF 30 30 00 50 33 32 30 EF",
            "FF 30 30 00 51 32 36 35 EF",
            "FF 30 30 00 64 31 37 45 46 35 38 33 30 45 EF"),
        sent);
    assertEquals(0.0, camera.getPan());
    assertEquals(true, camera.getPower());
  }

  @Test
  void requestsAreClampedToTheLimits() {
    camera.panTilt(120, -45);
    assertEquals(98.0, camera.getPan());
    assertEquals(-30.0, camera.getTilt());
    assertEquals(VCC4Packets.toHex(VCC4Packets.panTilt(98, -30)), sent.get(0));
    camera.zoom(5000);
    assertEquals(1960, camera.getZoom());
    assertEquals("FF 30 30 00 B3 30 37 41 38 EF", sent.get(1));
    camera.tiltRel(10);
    assertEquals(-20.0, camera.getTilt());
    assertEquals(98.0, camera.getPan(), "relative tilt keeps the pan");
    camera.panRel(-8);
    assertEquals(90.0, camera.getPan());
    camera.zoomRel(-2000);
    assertEquals(0, camera.getZoom());
    camera.panSlew(500);
    assertEquals(90.0, camera.getPanSlew());
    assertEquals(98.0, camera.getMaxPosPan());
    assertEquals(-98.0, camera.getMaxNegPan());
    assertEquals(88.0, camera.getMaxPosTilt());
    assertEquals(-30.0, camera.getMaxNegTilt());
    assertEquals(1960, camera.getMaxZoom());
    assertEquals("vcc4", camera.getTypeName());
  }

  @Test
  void anInvertedCameraFlipsSigns() {
    ArVCC4 inverted = new ArVCC4(f -> sent.add(VCC4Packets.toHex(f)), true);
    inverted.panTilt(90, 30);
    assertEquals(VCC4Packets.toHex(VCC4Packets.panTilt(-90, -30)), sent.get(0));
    assertEquals(90.0, inverted.getPan(), "the caller still sees its own angles");
  }

  @Test
  void invalidArgumentsAreRejected() {
    assertThrows(
        IllegalArgumentException.class,
        () -> new ArVCC4((java.util.function.Consumer<byte[]>) null));
    assertThrows(IllegalArgumentException.class, () -> VCC4Packets.ledControl(5));
    assertThrows(IllegalArgumentException.class, () -> VCC4Packets.digitalZoom(4));
    assertThrows(IllegalArgumentException.class, () -> VCC4Packets.zoom(-1));
    assertThrows(IllegalArgumentException.class, () -> new ArVCC4((org.jaria.robot.ArRobot) null));
  }
}
