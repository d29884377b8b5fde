package org.jaria.params;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ArRobotParamsTest {

  private static ParamFile file(String text, String name) throws ParamFormatException {
    return ParamFile.parse(text, name);
  }

  @Test
  void defaultsAreAGenericPioneer() {
    ArRobotParams d = ArRobotParams.defaults();
    assertEquals("Pioneer", d.getClassName());
    assertEquals("", d.getSubClassName());
    assertEquals(250, d.getRobotRadius());
    assertEquals(400, d.getRobotWidth());
    assertEquals(500, d.getRobotLength());
    assertEquals(250, d.getRobotLengthFront(), "0 means half the length");
    assertEquals(250, d.getRobotLengthRear());
    assertEquals(0.001534, d.getAngleConvFactor());
    assertEquals(1.0, d.getDistConvFactor());
    assertEquals(20, d.getVel2Divisor());
    assertEquals(1.626, d.getGyroScaler());
    assertEquals(2200, d.getAbsoluteMaxVelocity());
    assertEquals(500, d.getAbsoluteMaxRotVelocity());
    assertEquals(38400, d.getSwitchToBaudRate());
    assertEquals(0, d.getNumSonar());
    assertEquals(0, d.getNumIR());
    assertEquals(5, d.getNumFrontBumpers());
    assertTrue(d.hasMoveCommand());
    assertTrue(d.hasSettableVelMaxes());
    assertEquals("robot", d.getCompassType());
    assertEquals(0, d.getLaserMaxRange());
    assertEquals(Optional.of("standard"), d.getRaw("gpstype"));
  }

  @Test
  void forSubtypeLoadsTheBundledFile() {
    ArRobotParams p = ArRobotParams.forSubtype("P3DX-SH");
    assertEquals("p3dx-sh", p.getSubClassName());
    assertEquals(250, p.getRobotRadius());
    assertEquals(425, p.getRobotWidth());
    assertEquals(511, p.getRobotLength());
    assertEquals(210, p.getRobotLengthFront());
    assertEquals(301, p.getRobotLengthRear());
    assertEquals(16, p.getNumSonar());
    assertEquals(69, p.getSonarX(0));
    assertEquals(136, p.getSonarY(0));
    assertEquals(90, p.getSonarTh(0));
    assertEquals(-157, p.getSonarX(15));
    assertEquals(0.0056, p.getDiffConvFactor());
    assertEquals(2, p.getSources().size());
  }

  @Test
  void unknownSubtypeGivesDefaults() {
    assertSame(ArRobotParams.defaults(), ArRobotParams.forSubtype("hovercraft-9000"));
    assertSame(ArRobotParams.defaults(), ArRobotParams.forSubtype("../p3dx-sh"));
    assertSame(ArRobotParams.defaults(), ArRobotParams.forSubtype(null));
  }

  @Test
  void overlayReplacesKeywordsAndSonarUnitsByNumber() throws Exception {
    ArRobotParams base = ArRobotParams.forSubtype("p3dx-sh");
    ArRobotParams mine =
        base.overlay(
            file(
                """
                RobotRadius 300 ; bumpers fitted
                RobotLengthFront 0
                FrontBumpers TRUE
                SonarUnit 3 170 30 12
                MyOwnKeyword hello world
                """,
                "mybot.p"));
    assertEquals(300, mine.getRobotRadius());
    assertEquals(255.5, mine.getRobotLengthFront());
    assertTrue(mine.haveFrontBumpers());
    assertEquals(170, mine.getSonarX(3));
    assertEquals(12, mine.getSonarTh(3));
    assertEquals(148, mine.getSonarX(2), "other units are kept");
    assertEquals(16, mine.getNumSonar());
    assertEquals(Optional.of("hello world"), mine.getRaw("myownkeyword"));
    assertEquals("mybot.p:1", mine.getRawEntry("RobotRadius").orElseThrow().where());
    // The base is unchanged: parameters are immutable.
    assertEquals(250, base.getRobotRadius());
    assertEquals(166, base.getSonarX(3));
  }

  @Test
  void firstOccurrenceInAFileWins() throws Exception {
    ArRobotParams p =
        ArRobotParams.defaults()
            .overlay(
                file(
                    "Section Laser parameters\nLaserX 21\nSection Laser 2 parameters\nLaserX 99\n",
                    "two-lasers.p"));
    assertEquals(21, p.getLaserX());
  }

  @Test
  void mtxSonarUnitsAndIrUnitsParse() throws Exception {
    ArRobotParams p =
        ArRobotParams.defaults()
            .overlay(
                file(
                    """
                    SonarNum 2
                    SonarUnit 0 100 50 30 1 1 12 30 4000 false
                    SonarUnit 1 100 -50 -30 1 2
                    IRNum 1
                    IRUnit 0 1 2 333 -233
                    """,
                    "mtx.p"));
    SonarUnit u = p.getSonarUnit(0);
    assertEquals(new SonarUnit(0, 100, 50, 30, 1, 1, 12, 30, 4000, false), u);
    assertTrue(p.getSonarUnit(1).useForAutonomousDriving());
    assertEquals(2, p.getSonarUnit(1).mtxBoardUnit());
    assertEquals(1, p.getNumIR());
    assertEquals(333, p.getIRX(0));
    assertEquals(-233, p.getIRY(0));
    assertEquals(1, p.getIRType(0));
    assertEquals(2, p.getIRCycles(0));
    assertThrows(IndexOutOfBoundsException.class, () -> p.getSonarX(2));
    assertThrows(IndexOutOfBoundsException.class, () -> p.getIRX(-1));
  }

  @Test
  void sonarUnitWithTextIsATypedErrorNotAParseError() throws Exception {
    // The generic parser accepts any value text ...
    ParamFile f = file("Section Sonar parameters\nSonarNum 1\nSonarUnit 0 x y 90\n", "bad.p");
    assertEquals(Optional.of("0 x y 90"), f.get("SonarUnit"));
    // ... the typed layer says what is wrong, where.
    ParamFormatException e =
        assertThrows(ParamFormatException.class, () -> ArRobotParams.defaults().overlay(f));
    assertEquals("bad.p", e.getSourceName());
    assertEquals(3, e.getLine());
    assertTrue(
        e.getMessage().contains("SonarUnit x must be a whole number, not 'x'"), e.getMessage());
  }

  @Test
  void typedErrorsNameKeywordFileAndLine() throws Exception {
    assertTypedError("RobotRadius big\n", 1, "RobotRadius must be a number, not 'big'");
    assertTypedError("A 1\nMaxVelocity 1200.5\n", 2, "MaxVelocity must be a whole number");
    assertTypedError("Holonomic maybe\n", 1, "Holonomic must be true or false");
    assertTypedError("SonarUnit 0 1 2\n", 1, "SonarUnit needs 4 whole numbers");
    assertTypedError("SonarUnit -1 1 2 3\n", 1, "SonarUnit number -1 is out of range");
    assertTypedError("IRUnit 0 1 2 3\n", 1, "IRUnit needs 5 whole numbers");
    assertTypedError("SonarNum 100000\n", 1, "not a plausible sensor count");
    assertTypedError("GyroScaler NaN\n", 1, "GyroScaler must be a number");
    assertTypedError("RobotWidth\n", 1, "RobotWidth must be a number, not ''");
  }

  private static void assertTypedError(String text, int line, String expected) throws Exception {
    ParamFile f = file(text, "t.p");
    ParamFormatException e =
        assertThrows(ParamFormatException.class, () -> ArRobotParams.defaults().overlay(f));
    assertEquals(line, e.getLine(), e.getMessage());
    assertTrue(e.getMessage().startsWith("t.p:" + line + ": "), e.getMessage());
    assertTrue(e.getMessage().contains(expected), e.getMessage());
  }

  @Test
  void integersWrittenWithDecimalsAreAccepted() throws Exception {
    ArRobotParams p =
        ArRobotParams.defaults().overlay(file("MaxVelocity 1500.000\nSonarNum +0\n", "d.p"));
    assertEquals(1500, p.getAbsoluteMaxVelocity());
  }

  @Test
  void loadLayersBundledSubtypeThenRobotFile(@TempDir Path dir) throws Exception {
    Files.writeString(dir.resolve("Wall-E.p"), "RobotRadius 333\nSonarUnit 0 1 2 3\n");
    ArRobotParams p = ArRobotParams.load("p3at-sh", "Wall-E", dir);
    assertEquals("p3at-sh", p.getSubClassName());
    assertEquals(333, p.getRobotRadius());
    assertEquals(1, p.getSonarX(0));
    assertEquals(193, p.getSonarX(1));
    assertEquals(3, p.getSources().size());
    assertEquals(
        p.getRobotRadius(), ArRobotParams.loadStrict("p3at-sh", "Wall-E", dir).getRobotRadius());
  }

  @Test
  void userSubtypeFileReplacesTheBundledOne(@TempDir Path dir) throws Exception {
    Files.writeString(dir.resolve("p3dx-sh.p"), "Subclass p3dx-sh\nRobotWidth 999\n");
    ArRobotParams p = ArRobotParams.load("p3dx-sh", null, dir);
    assertEquals(999, p.getRobotWidth());
    assertEquals(0, p.getNumSonar(), "the bundled file was not loaded underneath");
  }

  @Test
  void brokenUserFileIsSkippedByLoadButFailsLoadStrict(@TempDir Path dir) throws Exception {
    Files.writeString(dir.resolve("bob.p"), "RobotRadius 300\nSonarUnit 0 a b c\n");
    ArRobotParams p = ArRobotParams.load("p3dx-sh", "bob", dir);
    assertEquals(250, p.getRobotRadius(), "the broken file is ignored as a whole");
    ParamFormatException e =
        assertThrows(
            ParamFormatException.class, () -> ArRobotParams.loadStrict("p3dx-sh", "bob", dir));
    assertEquals(2, e.getLine());
    assertTrue(e.getSourceName().endsWith("bob.p"));
  }

  @Test
  void robotNamesCannotEscapeTheParameterFolder(@TempDir Path dir) throws Exception {
    Path inner = Files.createDirectory(dir.resolve("params"));
    Files.writeString(dir.resolve("evil.p"), "RobotRadius 1\n");
    ArRobotParams p = ArRobotParams.load("p3dx-sh", "../evil", inner);
    assertEquals(250, p.getRobotRadius());
    assertFalse(p.getSources().stream().anyMatch(s -> s.contains("evil")));
  }

  @Test
  void missingUserDirIsFine() {
    ArRobotParams p = ArRobotParams.load("amigo-sh", "anything", null);
    assertEquals(180, p.getRobotRadius());
    assertEquals(8, p.getNumSonar());
  }
}
