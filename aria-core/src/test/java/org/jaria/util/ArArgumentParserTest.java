package org.jaria.util;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class ArArgumentParserTest {

  @Test
  void optionsAreTakenCaseInsensitivelyAndLeftoversReported() {
    ArArgumentParser p =
        new ArArgumentParser(new String[] {"-RP", "/dev/ttyUSB0", "-rb", "38400", "-extra"});
    assertEquals("/dev/ttyUSB0", p.checkParameterArgument("-robotPort", "-rp"));
    assertEquals(38400, p.checkParameterArgumentInteger(9600, "-robotBaud", "-rb"));
    assertNull(p.checkParameterArgument("-remoteHost", "-rh"));
    assertEquals(List.of("-extra"), p.getUnparsed());
    assertFalse(p.checkHelpAndWarnUnparsed());
  }

  @Test
  void helpIsRecognised() {
    ArArgumentParser p = new ArArgumentParser(new String[] {"-help"});
    assertTrue(p.checkHelp());
    assertTrue(p.isHelpRequested());
    assertFalse(p.checkHelpAndWarnUnparsed());
  }

  @Test
  void badValuesSayWhichOptionIsWrong() {
    ArArgumentParser p = new ArArgumentParser(new String[] {"-rb", "fast"});
    IllegalArgumentException e =
        assertThrows(
            IllegalArgumentException.class, () -> p.checkParameterArgumentInteger(1, "-rb"));
    assertTrue(e.getMessage().contains("-rb"));
    ArArgumentParser q = new ArArgumentParser(new String[] {"-rh"});
    assertThrows(IllegalArgumentException.class, () -> q.checkParameterArgument("-rh"));
  }
}
