package org.jaria.arnl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.config.ArConfig;
import org.jaria.config.ArConfigArg;
import org.jaria.config.ArConfigSection;
import org.junit.jupiter.api.Test;

class ArnlParamsTest {

  @Test
  void theBundledParamFileMatchesTheDefaults() throws Exception {
    ArConfig config = new ArConfig();
    new LocalizationParams(config);
    new PathPlanningParams(config);
    ArConfig.ParseResult r = Arnl.loadTypicalParams(config);
    assertTrue(r.warnings().isEmpty(), "every line is a known parameter: " + r.warnings());
    assertEquals(0, r.paramsChanged(), "the file holds the defaults");
    int total = 0;
    for (ArConfigSection s : config.getSections()) {
      for (ArConfigArg a : s.getParams()) {
        total++;
        assertFalse(a.getDescription().isEmpty(), a.getName() + " needs a description");
      }
    }
    assertEquals(total, r.paramsSet(), "the file lists every parameter");
    assertEquals(config.toText().lines().count(), Arnl.typicalParamFileText().lines().count() - 1);
  }
}
