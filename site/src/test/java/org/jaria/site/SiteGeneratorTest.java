package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The site builds from the repository, offline, with every guide and its assets. */
class SiteGeneratorTest {

  @Test
  void rendersEveryGuideWithWorkingLinks(@TempDir Path out) throws IOException {
    Path root = Repo.root();
    List<SiteGenerator.Page> pages = new SiteGenerator(root, out).generate();
    assertTrue(pages.size() >= 15, pages.size() + " pages");
    assertTrue(Files.isRegularFile(out.resolve("index.html")));
    assertTrue(Files.isRegularFile(out.resolve("style.css")));
    String home = Files.readString(out.resolve("docs/index.html"));
    assertTrue(home.contains("href=\"getting-started.html\""), "links point at HTML pages");
    assertTrue(home.contains("<nav>"), "every page has the navigation");
    String nav = home.substring(home.indexOf("<nav>"), home.indexOf("</nav>"));
    assertTrue(
        nav.indexOf(">Troubleshooting<") < nav.indexOf(">The classroom kit<"),
        "the navigation follows the documentation home's order, not the file names");
    String es = Files.readString(out.resolve("docs/es/primeros-pasos.html"));
    assertTrue(es.startsWith("<!DOCTYPE html>\n<html lang=\"es\">"), "Spanish page in Spanish");
    String porting = Files.readString(out.resolve("docs/porting-from-aria.html"));
    assertTrue(porting.contains("<table>"), "tables render");
    assertTrue(porting.contains("class=\"side-by-side\""), "C++ and Java side by side");
    assertTrue(
        Files.isRegularFile(out.resolve("docs/images/mapper-columbia.png")),
        "images the guides show are copied");
    assertTrue(
        Files.isRegularFile(out.resolve("classroom/assignments/square/starter/Square.java")),
        "files the guides link to are copied");
  }
}
