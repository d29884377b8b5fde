package org.jaria.laser;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.jaria.clock.Clock;
import org.jaria.connection.ArSerialConnection;
import org.jaria.connection.ArTcpConnection;
import org.jaria.params.ArRobotParams;
import org.jaria.util.ArArgumentParser;
import org.junit.jupiter.api.Test;

/** ARIA's laser parameter keys and command-line options, and the lasers they make. */
class LaserOptionsTest {

  private static final ArRobotParams P3DX = ArRobotParams.forSubtype("p3dx-sh");

  private static LaserOptions options(String... args) {
    ArArgumentParser p = new ArArgumentParser(args);
    Map<String, String> keys = LaserOptions.argsAsKeys(p);
    assertEquals(List.of(), p.getUnparsed(), "every laser option consumed");
    return LaserOptions.fromParamsAndArgs(P3DX::getRaw, keys);
  }

  @Test
  void theRobotsParametersDescribeItsLaser() {
    LaserOptions o = options();
    assertEquals("lms2xx", o.normalType());
    assertEquals("serial", o.portType());
    assertEquals("COM3", o.port());
    assertTrue(o.connect(), "LaserAutoConnect true");
    assertEquals(P3DX.getLaserX(), o.x());
    assertFalse(o.flipped());
    assertEquals(LmsSettings.DEFAULT, o.lmsSettings());
  }

  @Test
  void commandLineOptionsOverrideTheParameters() {
    LaserOptions o =
        options(
            "-lt",
            "sick",
            "-lp",
            "/dev/ttyUSB1",
            "-laserFlipped",
            "true",
            "-ld",
            "100",
            "-li",
            "quarter",
            "-lu",
            "1cm",
            "-lrb",
            "3ref",
            "-laserBaud",
            "19200",
            "-dncl");
    assertEquals("lms2xx", o.normalType());
    assertEquals("/dev/ttyUSB1", o.port());
    assertTrue(o.flipped());
    assertFalse(o.connect());
    assertEquals(new LmsSettings(100, 0.25, "1cm", 3, 19200), o.lmsSettings());
    LaserOptions u =
        options("-laserType", "urg2.0", "-lds", "-60", "-lde", "45", "-lsb", "115200", "-cl");
    assertEquals("urg", u.normalType());
    assertTrue(u.connect());
    assertEquals(new UrgSettings(-60, 45, 1, 115200, 115200), u.urgSettings());
  }

  @Test
  void theConnectorMakesTheRightLaserOnTheRightPort() {
    ArLaser lms = ArLaserConnector.createLaser(options("-lp", "/dev/ttyS9"), Clock.system());
    assertInstanceOf(ArLMS2xx.class, lms);
    assertInstanceOf(ArSerialConnection.class, lms.getDeviceConnection());
    assertEquals("serial /dev/ttyS9", lms.getDeviceConnection().getPortName());
    assertEquals(P3DX.getLaserX(), lms.getSensorPosition().x());
    ArLaser urg =
        ArLaserConnector.createLaser(
            options("-lt", "urg", "-lpt", "tcp", "-lp", "localhost:9555", "-lmr", "4000"),
            Clock.system());
    assertInstanceOf(ArUrg.class, urg);
    assertInstanceOf(ArTcpConnection.class, urg.getDeviceConnection());
    assertEquals(4000, urg.getMaxRange());
    assertNull(ArLaserConnector.createLaser(LaserOptions.NONE, Clock.system()));
  }

  @Test
  void badChoicesSayWhatIsExpected() {
    IllegalArgumentException e =
        assertThrows(
            IllegalArgumentException.class,
            () -> ArLaserConnector.createLaser(options("-lt", "lms5xx"), Clock.system()));
    assertEquals("unknown laser type 'lms5xx': use lms2xx (or sick) or urg", e.getMessage());
    e =
        assertThrows(
            IllegalArgumentException.class,
            () -> ArLaserConnector.createLaser(options("-lf", "maybe"), Clock.system()));
    assertEquals("LaserFlipped is true or false, not 'maybe'", e.getMessage());
    e =
        assertThrows(
            IllegalArgumentException.class,
            () -> ArLaserConnector.createLaser(options("-ld", "90"), Clock.system()));
    assertTrue(e.getMessage().contains("180 or 100"), e.getMessage());
    e =
        assertThrows(
            IllegalArgumentException.class,
            () ->
                ArLaserConnector.createLaser(
                    options("-lpt", "tcp", "-lp", "/dev/x"), Clock.system()));
    assertEquals("-laserPortType tcp needs -laserPort HOST:PORT", e.getMessage());
    assertThrows(
        IllegalArgumentException.class,
        () -> LaserOptions.argsAsKeys(new ArArgumentParser(new String[] {"-lp"})));
  }
}
