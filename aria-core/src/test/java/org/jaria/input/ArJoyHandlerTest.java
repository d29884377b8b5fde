package org.jaria.input;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The value-fed joystick. */
class ArJoyHandlerTest {

  @Test
  void noJoystickUntilConnected() {
    ArJoyHandler j = new ArJoyHandler();
    assertFalse(j.init());
    assertFalse(j.getButton(1));
    assertEquals(0, j.getAxis(1));
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> j.setAxis(1, 5));
    assertTrue(e.getMessage().contains("connect"));
    j.connect(2, 2);
    assertTrue(j.haveJoystick());
    assertFalse(j.haveZAxis());
    j.disconnect();
    assertFalse(j.haveJoystick());
  }

  @Test
  void osCalibratedValuesAreRawOver128() {
    ArJoyHandler j = new ArJoyHandler();
    j.connect(3, 4);
    j.setAxes(64, -128, 500);
    j.setButton(2, true);
    assertTrue(j.getButton(2));
    assertFalse(j.getButton(1));
    assertFalse(j.getButton(9));
    ArJoyHandler.JoyVec3f d = j.getDoubles();
    assertEquals(0.5, d.x(), 1e-9);
    assertEquals(-1, d.y(), 1e-9);
    assertEquals(1, d.z(), 1e-9, "clamped to 128");
    j.setSpeeds(400, 200, 10);
    assertEquals(new ArJoyHandler.JoyVec3i(200, -200, 10), j.getAdjusted());
    assertThrows(IllegalArgumentException.class, () -> j.setButton(5, true));
  }

  @Test
  void ownCalibrationKeepsTheSign() {
    ArJoyHandler j = new ArJoyHandler(false);
    j.connect(2, 1);
    j.setAxes(10, -6, 0);
    j.startCal();
    j.setAxes(110, 94, 0);
    j.setAxes(-40, -56, 0);
    j.setAxes(10, -6, 0);
    j.endCal();
    assertEquals(110, j.getStats()[0]);
    assertEquals(-40, j.getStats()[1]);
    j.setAxes(60, -31, 0);
    ArJoyHandler.JoyVec3f d = j.getDoubles();
    assertEquals(0.5, d.x(), 1e-9);
    assertEquals(-0.5, d.y(), 1e-9, "ARIA lost this sign");
  }
}
