package org.jaria.connection;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.clock.Clock;
import org.junit.jupiter.api.Test;

/** Robot addresses as a user types them. */
class RobotAddressTest {

  @Test
  void hostsAndPortsAreTcp() {
    RobotAddress a = RobotAddress.parse("robot1");
    assertFalse(a.isSerial());
    assertEquals("robot1:8101", a.toString());
    assertEquals(8102, RobotAddress.parse(" 10.0.0.5:8102 ").port());
    assertArrayEquals(
        new String[] {"-rh", "10.0.0.5", "-rrtp", "8102"},
        RobotAddress.parse("10.0.0.5:8102").toArgs());
    assertTrue(
        RobotAddress.parse("localhost:9").connection(Clock.system()) instanceof ArTcpConnection);
  }

  @Test
  void devicePathsAndComPortsAreSerial() {
    RobotAddress a = RobotAddress.parse("/dev/ttyS0");
    assertTrue(a.isSerial());
    assertEquals(9600, a.baud());
    assertEquals(115200, RobotAddress.parse("/dev/ttyUSB0@115200").baud());
    assertEquals("COM3", RobotAddress.parse("COM3").serialPort());
    assertArrayEquals(
        new String[] {"-rp", "/dev/ttyS0", "-rb", "38400"},
        RobotAddress.parse("/dev/ttyS0@38400").toArgs());
    assertTrue(a.connection(Clock.system()) instanceof ArSerialConnection);
  }

  @Test
  void nonsenseIsRefusedWithAnExample() {
    for (String bad : new String[] {"", "  ", "host:port", "host:0", "/dev/ttyS0@fast", ":8101"}) {
      IllegalArgumentException e =
          assertThrows(IllegalArgumentException.class, () -> RobotAddress.parse(bad), bad);
      assertFalse(e.getMessage().isBlank(), bad);
    }
    assertTrue(
        assertThrows(IllegalArgumentException.class, () -> RobotAddress.parse("h:x"))
            .getMessage()
            .contains("localhost:8101"));
  }
}
