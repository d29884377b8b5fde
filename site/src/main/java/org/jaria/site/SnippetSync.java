package org.jaria.site;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Keeps the code blocks of the guides equal to the source files they quote. In Markdown a quoted
 * block is written
 *
 * <pre>
 * &lt;!-- snippet: tools/src/main/java/org/jaria/tools/examples/Chase.java#fire --&gt;
 * ```java
 * ...
 * ```
 * </pre>
 *
 * so it reads well on GitHub and in the site alike; {@link #check} finds blocks that drifted from
 * their source, and {@code main} (run with {@code --update}) rewrites them.
 */
public final class SnippetSync {

  /** The marker line before a quoted block. */
  public static final Pattern MARKER = Pattern.compile("^<!-- snippet: (\\S+) -->\\s*$");

  private final Snippets snippets;

  /** Syncs against the repository at {@code root}. */
  public SnippetSync(Path root) {
    this.snippets = new Snippets(root);
  }

  /** One quoted block that differs from its source (or whose source is gone). */
  public record Drift(String file, int line, String ref, String problem) {
    @Override
    public String toString() {
      return file + ":" + line + ": " + ref + ": " + problem;
    }
  }

  /** The text with every quoted block replaced by its source, and the blocks that differed. */
  public record Result(String text, List<Drift> drifts) {}

  /** Syncs one Markdown text ({@code name} is for messages). */
  public Result sync(String name, String markdown) {
    String[] lines = markdown.split("\n", -1);
    StringBuilder out = new StringBuilder();
    List<Drift> drifts = new ArrayList<>();
    int i = 0;
    while (i < lines.length) {
      String line = lines[i];
      append(out, line, i, lines.length);
      Matcher m = MARKER.matcher(line);
      if (!m.matches()) {
        i++;
        continue;
      }
      String ref = m.group(1);
      int fence = i + 1;
      if (fence >= lines.length || !lines[fence].startsWith("```")) {
        drifts.add(new Drift(name, i + 1, ref, "the marker must be followed by a ``` block"));
        i++;
        continue;
      }
      int close = fence + 1;
      while (close < lines.length && !lines[close].startsWith("```")) {
        close++;
      }
      if (close >= lines.length) {
        drifts.add(new Drift(name, fence + 1, ref, "the ``` block is never closed"));
        i++;
        continue;
      }
      StringBuilder current = new StringBuilder();
      for (int k = fence + 1; k < close; k++) {
        current.append(lines[k]).append('\n');
      }
      String wanted;
      try {
        wanted = snippets.get(ref) + "\n";
      } catch (IOException | IllegalArgumentException e) {
        drifts.add(new Drift(name, i + 1, ref, e.getMessage()));
        i++;
        continue;
      }
      if (!wanted.contentEquals(current)) {
        drifts.add(
            new Drift(
                name,
                fence + 1,
                ref,
                "differs from its source; refresh the guides (docs/index.md says how)"));
      }
      append(out, lines[fence], fence, lines.length);
      out.append(wanted);
      append(out, lines[close], close, lines.length);
      i = close + 1;
    }
    return new Result(out.toString(), drifts);
  }

  private static void append(StringBuilder out, String line, int index, int count) {
    out.append(line);
    if (index < count - 1) {
      out.append('\n');
    }
  }

  /** Every drift in the documentation under {@code root}. */
  public List<Drift> check(Path root) throws IOException {
    List<Drift> all = new ArrayList<>();
    for (Path rel : DocFiles.list(root)) {
      String text = Files.readString(root.resolve(rel), StandardCharsets.UTF_8);
      all.addAll(sync(rel.toString(), text).drifts());
    }
    return all;
  }

  /**
   * Lists drifted blocks on {@code out}; with {@code update} rewrites them from their sources.
   *
   * @return the number of problems left (drifts not updated, missing sources)
   */
  public static int run(Path root, boolean update, java.io.PrintStream out) throws IOException {
    SnippetSync sync = new SnippetSync(root);
    int bad = 0;
    for (Path rel : DocFiles.list(root)) {
      Path file = root.resolve(rel);
      String text = Files.readString(file, StandardCharsets.UTF_8);
      Result r = sync.sync(rel.toString(), text);
      for (Drift d : r.drifts()) {
        out.println(d);
        if (!update || !d.problem().startsWith("differs")) {
          bad++;
        }
      }
      if (update && !r.text().equals(text)) {
        Files.writeString(file, r.text(), StandardCharsets.UTF_8);
        out.println("updated " + rel);
      }
    }
    return bad;
  }

  /** {@code SnippetSync ROOT [--update]}: exits 1 if problems remain. */
  public static void main(String[] args) throws IOException {
    Path root = Path.of(args.length > 0 ? args[0] : "..").toAbsolutePath().normalize();
    boolean update = args.length > 1 && args[1].equals("--update");
    System.exit(run(root, update, System.out) == 0 ? 0 : 1);
  }
}
