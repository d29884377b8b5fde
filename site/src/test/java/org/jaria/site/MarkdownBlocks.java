package org.jaria.site;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.commonmark.node.AbstractVisitor;
import org.commonmark.node.FencedCodeBlock;
import org.commonmark.node.IndentedCodeBlock;
import org.commonmark.node.Node;

/** The code blocks of the guides, as the site's Markdown parser sees them. */
final class MarkdownBlocks {

  private MarkdownBlocks() {}

  /** A code block: the file, its language ("" if none) and its text. */
  record Block(Path file, String language, String text) {}

  static List<Block> all(Path root) throws IOException {
    List<Block> out = new ArrayList<>();
    for (Path rel : DocFiles.list(root)) {
      Node doc =
          SiteGenerator.parser().parse(Files.readString(root.resolve(rel), StandardCharsets.UTF_8));
      doc.accept(
          new AbstractVisitor() {
            @Override
            public void visit(FencedCodeBlock b) {
              out.add(
                  new Block(rel, b.getInfo() == null ? "" : b.getInfo().strip(), b.getLiteral()));
            }

            @Override
            public void visit(IndentedCodeBlock b) {
              out.add(new Block(rel, "", b.getLiteral()));
            }
          });
    }
    return out;
  }
}
