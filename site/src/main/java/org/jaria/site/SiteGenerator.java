package org.jaria.site;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.commonmark.Extension;
import org.commonmark.ext.gfm.tables.TablesExtension;
import org.commonmark.ext.heading.anchor.HeadingAnchorExtension;
import org.commonmark.node.AbstractVisitor;
import org.commonmark.node.Heading;
import org.commonmark.node.Image;
import org.commonmark.node.Link;
import org.commonmark.node.Node;
import org.commonmark.node.Text;
import org.commonmark.parser.Parser;
import org.commonmark.renderer.html.HtmlRenderer;

/**
 * Builds the documentation site: every guide (README.md and docs/**.md) rendered to HTML with a
 * navigation bar, links between guides pointing at the HTML pages, and the repository files the
 * guides link to (images, sample sources) copied alongside. Pure Java, no network.
 *
 * <p>{@code SiteGenerator ROOT OUT} (the build runs it in the {@code site} module's package phase;
 * open {@code site/target/site/index.html}).
 */
public final class SiteGenerator {

  private static final List<Extension> EXTENSIONS =
      List.of(TablesExtension.create(), HeadingAnchorExtension.create());

  private final Path root;
  private final Path out;
  private final Parser parser = Parser.builder().extensions(EXTENSIONS).build();

  /** A generator reading the repository at {@code root} and writing the site into {@code out}. */
  public SiteGenerator(Path root, Path out) {
    this.root = root.toAbsolutePath().normalize();
    this.out = out.toAbsolutePath().normalize();
  }

  /** The Markdown parser the site uses (tables, heading anchors), for checks that parse guides. */
  public static Parser parser() {
    return Parser.builder().extensions(EXTENSIONS).build();
  }

  /** One page: its source, where it goes, its title. */
  record Page(Path source, Path target, String title) {}

  /**
   * Writes the site.
   *
   * @return the pages written
   */
  public List<Page> generate() throws IOException {
    Files.createDirectories(out);
    List<Page> pages = new ArrayList<>();
    for (Path rel : readingOrder()) {
      String md = Files.readString(root.resolve(rel), StandardCharsets.UTF_8);
      pages.add(new Page(rel, htmlPath(rel), title(parser.parse(md), rel)));
    }
    Set<Path> assets = new LinkedHashSet<>();
    for (Page p : pages) {
      String md = Files.readString(root.resolve(p.source()), StandardCharsets.UTF_8);
      Node doc = parser.parse(md);
      assets.addAll(rewriteLinks(doc, p.source()));
      String body = HtmlRenderer.builder().extensions(EXTENSIONS).build().render(doc);
      Path target = out.resolve(p.target());
      Files.createDirectories(target.getParent());
      Files.writeString(target, page(p, pages, body), StandardCharsets.UTF_8);
    }
    for (Path a : assets) {
      Path target = out.resolve(a);
      Files.createDirectories(target.getParent());
      Files.copy(root.resolve(a), target, StandardCopyOption.REPLACE_EXISTING);
    }
    Files.writeString(out.resolve("style.css"), STYLE, StandardCharsets.UTF_8);
    Files.writeString(
        out.resolve("index.html"),
        "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>JAria documentation</title>"
            + "<meta http-equiv=\"refresh\" content=\"0; url=docs/index.html\"></head><body>"
            + "<a href=\"docs/index.html\">JAria documentation</a></body></html>\n",
        StandardCharsets.UTF_8);
    return pages;
  }

  /**
   * The guides in the order the documentation home (docs/index.md) lists them, the home first; the
   * README and any guide the home does not link come after.
   */
  List<Path> readingOrder() throws IOException {
    Path home = Path.of("docs", "index.md");
    Set<Path> order = new LinkedHashSet<>();
    order.add(home);
    parser
        .parse(Files.readString(root.resolve(home), StandardCharsets.UTF_8))
        .accept(
            new AbstractVisitor() {
              @Override
              public void visit(Link link) {
                String d = link.getDestination();
                String path = d.contains("#") ? d.substring(0, d.indexOf('#')) : d;
                if (path.endsWith(".md") && !d.contains("://")) {
                  Path p = home.getParent().resolve(path).normalize();
                  if (Files.isRegularFile(root.resolve(p))) {
                    order.add(p);
                  }
                }
                visitChildren(link);
              }
            });
    order.addAll(DocFiles.list(root));
    return new ArrayList<>(order);
  }

  static Path htmlPath(Path md) {
    String s = md.toString();
    return Path.of(s.substring(0, s.length() - ".md".length()) + ".html");
  }

  private static String title(Node doc, Path rel) {
    String[] t = {null};
    doc.accept(
        new AbstractVisitor() {
          @Override
          public void visit(Heading h) {
            if (t[0] == null) {
              StringBuilder sb = new StringBuilder();
              h.accept(
                  new AbstractVisitor() {
                    @Override
                    public void visit(Text text) {
                      sb.append(text.getLiteral());
                    }
                  });
              t[0] = sb.toString();
            }
          }
        });
    return t[0] != null ? t[0] : rel.getFileName().toString();
  }

  /**
   * Points links to guides at their HTML pages; returns the other repository files the page links
   * to (to copy into the site, so the links work there too).
   */
  private Set<Path> rewriteLinks(Node doc, Path page) {
    Set<Path> assets = new LinkedHashSet<>();
    Path dir = page.getParent() == null ? Path.of("") : page.getParent();
    doc.accept(
        new AbstractVisitor() {
          @Override
          public void visit(Link link) {
            link.setDestination(rewrite(link.getDestination()));
            visitChildren(link);
          }

          @Override
          public void visit(Image image) {
            rewrite(image.getDestination());
            visitChildren(image);
          }

          private String rewrite(String dest) {
            if (dest.contains("://") || dest.startsWith("#") || dest.startsWith("mailto:")) {
              return dest;
            }
            int hash = dest.indexOf('#');
            String path = hash < 0 ? dest : dest.substring(0, hash);
            String frag = hash < 0 ? "" : dest.substring(hash);
            if (path.endsWith(".md")) {
              return path.substring(0, path.length() - 3) + ".html" + frag;
            }
            Path target = dir.resolve(path).normalize();
            if (!target.startsWith("..") && Files.isRegularFile(root.resolve(target))) {
              assets.add(target);
            }
            return dest;
          }
        });
    return assets;
  }

  private String page(Page p, List<Page> pages, String body) {
    Path dir = p.target().getParent() == null ? Path.of("") : p.target().getParent();
    StringBuilder nav = new StringBuilder("<nav><p><b>JAria</b></p><ul>\n");
    for (Page other : pages) {
      String href = dir.relativize(other.target()).toString().replace('\\', '/');
      nav.append("<li")
          .append(other.equals(p) ? " class=\"here\"" : "")
          .append("><a href=\"")
          .append(href)
          .append("\">")
          .append(esc(other.title()))
          .append("</a></li>\n");
    }
    String up = dir.relativize(Path.of("")).toString().replace('\\', '/');
    String prefix = up.isEmpty() ? "" : up + "/";
    if (Files.isRegularFile(out.resolve("apidocs/index.html"))) {
      nav.append("<li><a href=\"")
          .append(prefix)
          .append("apidocs/index.html\">API (Javadoc)</a></li>\n");
    }
    nav.append("</ul></nav>\n");
    String lang = p.source().startsWith(Path.of("docs", "es")) ? "es" : "en";
    return "<!DOCTYPE html>\n<html lang=\""
        + lang
        + "\"><head><meta charset=\"utf-8\"><meta name=\"viewport\""
        + " content=\"width=device-width, initial-scale=1\"><title>"
        + esc(p.title())
        + " — JAria</title><link rel=\"stylesheet\" href=\""
        + prefix
        + "style.css\"></head><body>\n"
        + nav
        + "<main>\n"
        + body
        + "</main></body></html>\n";
  }

  private static String esc(String s) {
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
  }

  private static final String STYLE =
      """
      body{margin:0;font:16px/1.5 system-ui,sans-serif;color:#222;display:flex}
      nav{width:16em;flex:none;padding:1em;background:#f4f4f2;min-height:100vh;font-size:14px}
      nav ul{list-style:none;padding:0}nav li{margin:.3em 0}nav li.here a{font-weight:bold}
      main{flex:1;min-width:0;max-width:80em;padding:1em 2em;overflow-x:auto}
      table{font-size:14px}
      pre{background:#f6f8fa;padding:.8em;overflow-x:auto;font-size:13px}
      code{font-family:ui-monospace,monospace}
      table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:.3em .6em;vertical-align:top}
      .side-by-side{display:grid;grid-template-columns:minmax(0,1fr) minmax(0,1fr);gap:1em}
      .side-by-side pre{margin:0;height:100%}
      img{max-width:100%}
      """;

  /** {@code SiteGenerator ROOT OUT}. */
  public static void main(String[] args) throws IOException {
    if (args.length != 2) {
      System.err.println("usage: SiteGenerator REPOSITORY_ROOT OUTPUT_DIR");
      System.exit(2);
    }
    Path outDir = Path.of(args[1]);
    List<Page> pages = new SiteGenerator(Path.of(args[0]), outDir).generate();
    System.out.println(
        "site: "
            + pages.size()
            + " pages in "
            + outDir.toAbsolutePath().normalize()
            + "/index.html");
  }
}
