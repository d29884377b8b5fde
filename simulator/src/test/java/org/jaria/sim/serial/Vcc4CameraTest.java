package org.jaria.sim.serial;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.util.HexFormat;
import org.junit.jupiter.api.Test;

class Vcc4CameraTest {

  private static final HexFormat HEX = HexFormat.of();

  private static byte[] send(Vcc4Camera cam, String hex) {
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    cam.receive(HEX.parseHex(hex), out::writeBytes);
    return out.toByteArray();
  }

  private static Vcc4Camera ready() {
    Vcc4Camera cam = new Vcc4Camera();
    send(cam, "ff303000a031ef");
    send(cam, "ff3030009030ef");
    return cam;
  }

  @Test
  void commandsBeforeHostControlModeGetTheModeError() {
    Vcc4Camera cam = new Vcc4Camera();
    assertArrayEquals(HEX.parseHex("fe30303930ef"), send(cam, "ff3030005830ef"), "init");
    assertArrayEquals(HEX.parseHex("fe30303030ef"), send(cam, "ff303000a031ef"), "power on");
    assertArrayEquals(HEX.parseHex("fe30303030ef"), send(cam, "ff3030009030ef"), "host mode");
    assertArrayEquals(HEX.parseHex("fe30303030ef"), send(cam, "ff3030005830ef"), "init now");
  }

  @Test
  void panTiltAndZoomArePositionedAndReported() {
    Vcc4Camera cam = ready();
    // pan 8320h = +90 degrees, tilt 7EF5h = -30 (the manual's example)
    assertArrayEquals(HEX.parseHex("fe30303030ef"), send(cam, "ff303000623833323037454635ef"));
    assertEquals(90, cam.getPan(), 0.06);
    assertEquals(-30, cam.getTilt(), 0.06);
    assertArrayEquals(
        HEX.parseHex("fe303030303833323037454635ef"), send(cam, "ff30300063ef"), "14 bytes");
    assertArrayEquals(HEX.parseHex("fe30303030ef"), send(cam, "ff303000b330313030ef"));
    assertArrayEquals(HEX.parseHex("fe3030303030313030ef"), send(cam, "ff303000b430ef"));
    assertEquals(256, cam.getZoom());
  }

  @Test
  void outOfRangeOrNonHexParametersGetTheParameterError() {
    Vcc4Camera cam = ready();
    byte[] param = HEX.parseHex("fe30303530ef");
    assertArrayEquals(param, send(cam, "ff303000623935303038303030ef"), "pan 9500h: too far");
    assertArrayEquals(param, send(cam, "ff303000623830303038334e30ef"), "tilt not hex");
    assertArrayEquals(param, send(cam, "ff30300062ef"), "no parameters");
    assertArrayEquals(param, send(cam, "ff30300001ef"), "unknown command");
    assertEquals(0, cam.getPan(), 1e-9, "nothing moved");
  }

  @Test
  void noiseAndBrokenFramesAreSkippedAndTheNextFrameIsAnswered() {
    Vcc4Camera cam = new Vcc4Camera();
    byte[] got = send(cam, "0102ef" + "ff3030" + "ff303000a031ef");
    assertArrayEquals(HEX.parseHex("fe30303030ef"), got, "only the complete frame answered");
    assertEquals(6, cam.skippedBytes());
    StringBuilder flood = new StringBuilder("ff");
    for (int i = 0; i < 100; i++) {
      flood.append("30");
    }
    assertArrayEquals(new byte[0], send(cam, flood + "ef"), "an over-long frame is dropped");
    assertArrayEquals(HEX.parseHex("fe30303030ef"), send(cam, "ff3030009030ef"));
  }

  @Test
  void anAuxPortHoldsARequestUntilTheBytesAreThereAndDropsOldBytesWhenFull() {
    AuxPort port = new AuxPort(1, new Vcc4Camera());
    port.request(6);
    assertEquals(null, port.takeAnswer(), "nothing from the camera yet");
    port.write(HEX.parseHex("ff303000a031ef"));
    assertArrayEquals(HEX.parseHex("fe30303030ef"), port.takeAnswer());
    assertEquals(null, port.takeAnswer(), "answered once");
    for (int i = 0; i < 100; i++) {
      port.write(HEX.parseHex("ff303000a031ef"));
    }
    assertEquals(AuxPort.BUFFER_BYTES, port.buffered());
    assertEquals(600 - AuxPort.BUFFER_BYTES, port.dropped());
    port.request(0);
    assertEquals(0, port.buffered(), "GETAUX 0 flushes");
    AuxPort empty = new AuxPort(2, null);
    empty.request(10);
    assertArrayEquals(new byte[0], empty.takeAnswer(), "nothing attached: no bytes at once");
  }
}
