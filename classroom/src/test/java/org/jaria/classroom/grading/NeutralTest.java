package org.jaria.classroom.grading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import org.junit.jupiter.api.Test;

/** What a student wrote, made harmless for each place it is shown. */
class NeutralTest {

  @Test
  void terminalsNeverGetAnEscapeOrACarriageReturn() {
    String evil = "ana\u001b[2J\u001b]0;owned\u0007\rbob\u202eexe.txt";
    String t = Neutral.text(evil);
    assertFalse(t.contains("\u001b") || t.contains("\r") || t.contains("\u0007"), t);
    assertFalse(t.contains("\u202e"), t);
    assertEquals("ana?[2J?]0;owned?\nbob?exe.txt", t);
    assertEquals("a b", Neutral.line("a\nb"));
    assertEquals("a b", Neutral.text("a\tb"));
  }

  @Test
  void everySpreadsheetFormulaIsGuardedEvenAfterALineBreak() {
    assertEquals("\"'=1+1\"", Neutral.csv("=1+1"));
    assertEquals("\"'+cmd\"", Neutral.csv("+cmd"));
    assertEquals("\"'-2\"", Neutral.csv("-2"));
    assertEquals("\"'@SUM(A1)\"", Neutral.csv("@SUM(A1)"));
    assertEquals("\"'\tx\"", Neutral.csv("\tx"));
    assertEquals("\"ok\n'=HYPERLINK(\"\"x\"\")\"", Neutral.csv("ok\n=HYPERLINK(\"x\")"));
    assertEquals("\"a\n'=b\"", Neutral.csv("a\r=b"));
    assertEquals("plain", Neutral.csv("plain"));
    assertEquals("\"a,b\"", Neutral.csv("a,b"));
  }

  @Test
  void markdownAndHtmlGetNoRawMarkup() {
    assertEquals(
        "&lt;img src=x onerror=alert(1)&gt;", Neutral.html("<img src=x onerror=alert(1)>"));
    String md = Neutral.markdown("<script>|x|</script> [a](javascript:1) *b*");
    assertFalse(md.contains("<"), md);
    assertEquals("&lt;script&gt;\\|x\\|&lt;/script&gt; \\[a\\](javascript:1) \\*b\\*", md);
  }
}
