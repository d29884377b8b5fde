package org.jaria.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ArConfigTest {

  private final ArConfig config = new ArConfig();
  private final ArConfigArg samples =
      config.addParam(
          ArConfigArg.ofInt("NumSamples", 2000, "particles in the filter", 10, 100000),
          "Localization",
          ArPriority.IMPORTANT);
  private final ArConfigArg trigger =
      config.addParam(
          ArConfigArg.ofDouble("TriggerDistance", 200, "mm moved before an update", 0, 10000),
          "Localization");
  private final ArConfigArg adjust =
      config.addParam(ArConfigArg.ofBool("AdjustNumSamples", false, "KLD"), "Localization");
  private final ArConfigArg mapName =
      config.addParam(ArConfigArg.ofString("Map", "", "map file"), "Files");

  @Test
  void parsesTypedValuesCaseInsensitively() throws Exception {
    ArConfig.ParseResult r =
        config.parseText(
            """
            Section localization
            numsamples 500 ; fewer
            TriggerDistance 1.5e2
            AdjustNumSamples yes
            Section Files
            Map office.map
            """,
            "test.p");
    assertEquals(500, samples.getInt());
    assertEquals(150.0, trigger.getDouble());
    assertTrue(adjust.getBool());
    assertEquals("office.map", mapName.getString());
    assertEquals(4, r.paramsSet());
    assertEquals(4, r.paramsChanged());
    assertTrue(r.warnings().isEmpty());
  }

  @Test
  void outOfBoundsValueNamesFileAndLineAndChangesNothing() {
    ArConfigException e =
        assertThrows(
            ArConfigException.class,
            () ->
                config.parseText(
                    "Section Localization\nTriggerDistance 300\nNumSamples 5\n", "arnl.p"));
    assertEquals(3, e.getLine());
    assertTrue(e.getMessage().startsWith("arnl.p:3: "), e.getMessage());
    assertTrue(e.getMessage().contains("between 10 and 100000"), e.getMessage());
    assertEquals(200.0, trigger.getDouble(), "a rejected file must not apply any value");
  }

  @Test
  void countsSeveralBadValues() {
    ArConfigException e =
        assertThrows(
            ArConfigException.class,
            () ->
                config.parseText(
                    """
                    Section Localization
                    NumSamples many
                    AdjustNumSamples maybe
                    TriggerDistance nan
                    """,
                    "x.p"));
    assertEquals(2, e.getLine());
    assertTrue(e.getMessage().contains("and 2 more bad values"), e.getMessage());
  }

  @Test
  void unknownSectionsAndParamsAreWarningsNotErrors() throws Exception {
    ArConfig.ParseResult r =
        config.parseText(
            """
            Section Path Planning
            PlanRes 100
            Section Localization
            NumSampels 10
            NumSamples 300
            """,
            "mixed.p");
    assertEquals(300, samples.getInt());
    assertEquals(2, r.warnings().size());
    assertTrue(r.warnings().get(0).startsWith("mixed.p:2: unknown section"), r.warnings().get(0));
    assertTrue(r.warnings().get(1).contains("NumSampels"), r.warnings().get(1));
  }

  @Test
  void savesAndLoadsBack(@TempDir Path dir) throws Exception {
    samples.setInt(1234);
    trigger.setDouble(0.125);
    adjust.setBool(true);
    mapName.setString("columbia.map");
    Path f = dir.resolve("saved.p");
    config.writeFile(f);
    String text = Files.readString(f);
    assertTrue(text.contains("Section Localization"), text);
    assertTrue(text.contains("(between 10 and 100000)"), text);

    ArConfig other = new ArConfig();
    ArConfigArg s2 =
        other.addParam(ArConfigArg.ofInt("NumSamples", 1, "", 0, 100000), "Localization");
    ArConfigArg t2 = other.addParam(ArConfigArg.ofDouble("TriggerDistance", 1, ""), "Localization");
    ArConfigArg a2 =
        other.addParam(ArConfigArg.ofBool("AdjustNumSamples", false, ""), "Localization");
    ArConfigArg m2 = other.addParam(ArConfigArg.ofString("Map", "", ""), "Files");
    ArConfig.ParseResult r = other.parseFile(f);
    assertEquals(1234, s2.getInt());
    assertEquals(0.125, t2.getDouble());
    assertTrue(a2.getBool());
    assertEquals("columbia.map", m2.getString());
    assertTrue(r.warnings().isEmpty(), r.warnings().toString());
  }

  @Test
  void callbacksRunByPriorityAndCanReject() throws Exception {
    List<String> order = new ArrayList<>();
    config.addProcessFileCB(
        () -> {
          order.add("low");
          return true;
        },
        10);
    config.addProcessFileCB(
        () -> {
          order.add("high");
          return true;
        },
        90);
    config.parseText("Section Localization\nNumSamples 100\n", "a.p");
    assertEquals(List.of("high", "low"), order);

    config.addProcessFileCB(() -> false, 50);
    ArConfigException e =
        assertThrows(
            ArConfigException.class,
            () -> config.parseText("Section Localization\nNumSamples 200\n", "b.p"));
    assertTrue(e.getMessage().contains("rejected"), e.getMessage());
  }

  @Test
  void changeListenersHearOnlyRealChanges() throws Exception {
    AtomicInteger calls = new AtomicInteger();
    samples.addChangeListener(a -> calls.incrementAndGet());
    samples.setInt(2000);
    assertEquals(0, calls.get());
    config.parseText("Section Localization\nNumSamples 2500\n", "c.p");
    assertEquals(1, calls.get());
    assertEquals(2500, samples.getInt());
  }

  @Test
  void settersCheckBoundsAndTypes() {
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> samples.setInt(1_000_000));
    assertTrue(e.getMessage().contains("NumSamples"), e.getMessage());
    assertThrows(IllegalArgumentException.class, () -> trigger.setDouble(Double.NaN));
    assertThrows(IllegalArgumentException.class, () -> mapName.setString("a;b"));
    assertThrows(IllegalStateException.class, samples::getBool);
    assertThrows(IllegalArgumentException.class, () -> ArConfigArg.ofInt("two words", 1, ""));
    assertThrows(
        IllegalArgumentException.class,
        () -> config.addParam(ArConfigArg.ofInt("numsamples", 1, ""), "LOCALIZATION"));
    assertEquals(2000, samples.getInt());
    assertFalse(samples.isChanged());
  }

  @Test
  void commandLineStyleSetting() {
    config.setParamFromText("triggerdistance", "250");
    assertEquals(250.0, trigger.getDouble());
    IllegalArgumentException e =
        assertThrows(
            IllegalArgumentException.class, () -> config.setParamFromText("NoSuchThing", "1"));
    assertTrue(e.getMessage().contains("NumSamples"), e.getMessage());
  }

  @Test
  void malformedLinesNameTheLine(@TempDir Path dir) throws IOException {
    Path f = dir.resolve("bad.p");
    Files.writeString(f, "Section Localization\n  = 5\n");
    ArConfigException e = assertThrows(ArConfigException.class, () -> config.parseFile(f));
    assertEquals(2, e.getLine());
    assertTrue(e.getMessage().startsWith(f + ":2: "), e.getMessage());
  }

  @Test
  void seededGarbageNeverCrashes() {
    Random rnd = new Random(42);
    String alphabet = "Section Localization NumSamples Trigger 0123456789.-e;#[]\n\t xyz\u00e9\r";
    int rejected = 0;
    for (int i = 0; i < 500; i++) {
      StringBuilder sb = new StringBuilder();
      int n = rnd.nextInt(200);
      for (int k = 0; k < n; k++) {
        sb.append(alphabet.charAt(rnd.nextInt(alphabet.length())));
      }
      try {
        config.parseText(sb.toString(), "fuzz" + i);
      } catch (ArConfigException e) {
        rejected++;
        assertTrue(e.getMessage().startsWith("fuzz" + i + ":"), e.getMessage());
      }
      assertTrue(samples.getInt() >= 10 && samples.getInt() <= 100000);
    }
    assertTrue(rejected > 0, "the fuzzer should produce some invalid files");
  }
}
