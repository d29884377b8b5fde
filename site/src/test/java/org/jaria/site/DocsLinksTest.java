package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.commonmark.ext.heading.anchor.IdGenerator;
import org.commonmark.node.AbstractVisitor;
import org.commonmark.node.Heading;
import org.commonmark.node.Image;
import org.commonmark.node.Link;
import org.commonmark.node.Node;
import org.commonmark.node.Text;
import org.junit.jupiter.api.Test;

/** Every link between guides (and to repository files) points at something that exists. */
class DocsLinksTest {

  private final Path root = Repo.root();

  @Test
  void everyRelativeLinkAndAnchorResolves() throws IOException {
    List<String> broken = new ArrayList<>();
    int checked = 0;
    for (Path rel : DocFiles.list(root)) {
      Node doc = parse(rel);
      Path dir = rel.getParent() == null ? Path.of("") : rel.getParent();
      for (String dest : destinations(doc)) {
        if (dest.contains("://") || dest.startsWith("mailto:")) {
          continue;
        }
        checked++;
        int hash = dest.indexOf('#');
        String path = hash < 0 ? dest : dest.substring(0, hash);
        String anchor = hash < 0 ? null : dest.substring(hash + 1);
        Path target = path.isEmpty() ? rel : dir.resolve(path).normalize();
        if (!Files.exists(root.resolve(target))) {
          broken.add(rel + ": " + dest + " (no " + target + ")");
          continue;
        }
        if (anchor != null && target.toString().endsWith(".md")) {
          if (!anchors(parse(target)).contains(anchor)) {
            broken.add(rel + ": " + dest + " (no heading #" + anchor + " in " + target + ")");
          }
        }
      }
    }
    assertEquals(List.of(), broken, "broken links");
    assertTrue(checked >= 40, "only " + checked + " links checked");
  }

  @Test
  void everyGuideIsReachableFromTheDocumentationHome() throws IOException {
    Set<Path> reached = new HashSet<>();
    List<Path> todo = new ArrayList<>(List.of(Path.of("docs", "index.md")));
    while (!todo.isEmpty()) {
      Path p = todo.remove(todo.size() - 1);
      if (!reached.add(p)) {
        continue;
      }
      Path dir = p.getParent();
      for (String dest : destinations(parse(p))) {
        String path = dest.contains("#") ? dest.substring(0, dest.indexOf('#')) : dest;
        if (path.endsWith(".md") && !dest.contains("://")) {
          Path t = dir.resolve(path).normalize();
          if (Files.exists(root.resolve(t))) {
            todo.add(t);
          }
        }
      }
    }
    List<Path> orphans = new ArrayList<>(DocFiles.list(root));
    orphans.removeAll(reached);
    orphans.remove(Path.of("README.md"));
    assertEquals(List.of(), orphans, "guides no link leads to from docs/index.md");
  }

  @Test
  void theReadmeLinksIntoTheGuides() throws IOException {
    List<String> d = destinations(parse(Path.of("README.md")));
    assertTrue(d.contains("docs/index.md"), d.toString());
    assertTrue(d.contains("docs/getting-started.md"), d.toString());
    assertTrue(d.contains("docs/es/primeros-pasos.md"), d.toString());
  }

  private Node parse(Path rel) throws IOException {
    return SiteGenerator.parser()
        .parse(Files.readString(root.resolve(rel), StandardCharsets.UTF_8));
  }

  private static List<String> destinations(Node doc) {
    List<String> out = new ArrayList<>();
    doc.accept(
        new AbstractVisitor() {
          @Override
          public void visit(Link link) {
            out.add(link.getDestination());
            visitChildren(link);
          }

          @Override
          public void visit(Image image) {
            out.add(image.getDestination());
          }
        });
    return out;
  }

  /** The heading ids the site gives a page (commonmark's heading-anchor rule, as GitHub's). */
  private static Set<String> anchors(Node doc) {
    IdGenerator ids = IdGenerator.builder().build();
    Set<String> out = new HashSet<>();
    doc.accept(
        new AbstractVisitor() {
          @Override
          public void visit(Heading h) {
            StringBuilder sb = new StringBuilder();
            h.accept(
                new AbstractVisitor() {
                  @Override
                  public void visit(Text t) {
                    sb.append(t.getLiteral());
                  }

                  @Override
                  public void visit(org.commonmark.node.Code c) {
                    sb.append(c.getLiteral());
                  }
                });
            out.add(ids.generateId(sb.toString()));
          }
        });
    return out;
  }
}
