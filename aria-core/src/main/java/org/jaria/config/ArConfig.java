package org.jaria.config;

import java.io.IOException;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BooleanSupplier;
import org.jaria.params.ParamFile;
import org.jaria.params.ParamFormatException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A registry of typed configuration parameters grouped in sections, loaded from and saved to a text
 * file (ARIA's {@code ArConfig}, thesis §5.1.30). Modules register their parameters with {@link
 * #addParam}; a file ({@code arnl.p}, say) sets them with {@link #parseFile}; modules that must
 * react to a new configuration as a whole (rebuild a grid, resize a filter) register a process-file
 * callback with {@link #addProcessFileCB}. Single parameters also report their own changes ({@link
 * ArConfigArg#addChangeListener}).
 *
 * <p>The file format is ARIA's:
 *
 * <pre>
 * Section Localization
 * ; Monte Carlo localization with sonar
 * NumSamples 2000        ; particles in the filter (between 10 and 100000)
 * TriggerDistance 200    ; mm moved before an update
 * </pre>
 *
 * <p>Parameter and section names are compared case-insensitively. A file is applied all or nothing:
 * if any value is malformed or out of bounds, {@link #parseFile} throws an {@link
 * ArConfigException} naming the file and line, and no value changes. Unknown sections and
 * parameters are not errors (a file may configure modules this program does not use); they are
 * logged and listed in the {@link ParseResult}.
 *
 * <p>Thread-safe. There is no global instance: create one and pass it to the modules that use it.
 */
public final class ArConfig {

  private static final Logger log = LoggerFactory.getLogger(ArConfig.class);

  private final List<ArConfigSection> sections = new CopyOnWriteArrayList<>();
  private final List<Callback> callbacks = new CopyOnWriteArrayList<>();

  private record Callback(BooleanSupplier cb, int priority, long order) {}

  private long callbackCount;

  /**
   * What loading a file did.
   *
   * @param source the file (or description) that was loaded
   * @param paramsSet how many parameter lines were applied
   * @param paramsChanged how many of them changed a value
   * @param warnings unknown sections and parameters, as "file:line: ..." messages
   */
  public record ParseResult(
      String source, int paramsSet, int paramsChanged, List<String> warnings) {

    /** Copies the warnings. */
    public ParseResult {
      warnings = List.copyOf(warnings);
    }
  }

  /** An empty configuration. */
  public ArConfig() {}

  // ------------------------------------------------------------------ registering

  /**
   * Adds a section (or returns the existing one of that name, updating its comment if {@code
   * comment} is not blank).
   */
  public synchronized ArConfigSection addSection(String name, String comment) {
    String n = checkSectionName(name);
    for (ArConfigSection s : sections) {
      if (s.isNamed(n)) {
        s.setComment(comment);
        return s;
      }
    }
    ArConfigSection s = new ArConfigSection(n, comment);
    sections.add(s);
    return s;
  }

  private static String checkSectionName(String name) {
    Objects.requireNonNull(name, "a section needs a name");
    String n = name.strip();
    if (n.isEmpty() || n.indexOf(';') >= 0 || n.chars().anyMatch(Character::isISOControl)) {
      throw new IllegalArgumentException(
          "section name '" + name + "' must be non-empty text without ';'");
    }
    return n;
  }

  /** Adds a parameter to a section (created if needed) with {@link ArPriority#NORMAL}. */
  public ArConfigArg addParam(ArConfigArg arg, String sectionName) {
    return addParam(arg, sectionName, ArPriority.NORMAL);
  }

  /**
   * Adds a parameter to a section (created if needed). Adding the same parameter object again only
   * updates its priority.
   *
   * @return {@code arg}, for chaining
   * @throws IllegalArgumentException if another parameter of that name is already in the section
   */
  public synchronized ArConfigArg addParam(
      ArConfigArg arg, String sectionName, ArPriority priority) {
    Objects.requireNonNull(arg, "arg");
    ArConfigSection s = addSection(sectionName, "");
    Optional<ArConfigArg> old = s.findParam(arg.getName());
    if (old.isPresent() && old.get() != arg) {
      throw new IllegalArgumentException(
          "section '"
              + s.getName()
              + "' already has a parameter called "
              + old.get().getName()
              + "; give the new one another name or remove the old one first");
    }
    arg.setPriority(priority);
    if (old.isEmpty()) {
      s.add(arg);
    }
    return arg;
  }

  /** Removes the parameter {@code paramName} from a section; returns whether it was there. */
  public synchronized boolean remParam(String sectionName, String paramName) {
    return findSection(sectionName).map(s -> s.remove(paramName)).orElse(false);
  }

  /** The section called {@code name} (case-insensitive). */
  public Optional<ArConfigSection> findSection(String name) {
    for (ArConfigSection s : sections) {
      if (s.isNamed(name)) {
        return Optional.of(s);
      }
    }
    return Optional.empty();
  }

  /** The parameter {@code paramName} of section {@code sectionName}. */
  public Optional<ArConfigArg> findParam(String sectionName, String paramName) {
    return findSection(sectionName).flatMap(s -> s.findParam(paramName));
  }

  /** The first parameter called {@code paramName} in any section. */
  public Optional<ArConfigArg> findParam(String paramName) {
    for (ArConfigSection s : sections) {
      Optional<ArConfigArg> a = s.findParam(paramName);
      if (a.isPresent()) {
        return a;
      }
    }
    return Optional.empty();
  }

  /** The sections in the order they were added. */
  public List<ArConfigSection> getSections() {
    return List.copyOf(sections);
  }

  /**
   * Registers a callback run after a file has been loaded (and by {@link
   * #callProcessFileCallBacks}); higher priorities run first, equal ones in the order added. A
   * callback returns false to reject the new configuration (the load then fails).
   */
  public synchronized void addProcessFileCB(BooleanSupplier cb, int priority) {
    callbacks.add(new Callback(Objects.requireNonNull(cb, "callback"), priority, callbackCount++));
  }

  /** Removes a process-file callback. */
  public void remProcessFileCB(BooleanSupplier cb) {
    callbacks.removeIf(c -> c.cb() == cb);
  }

  /**
   * Runs every process-file callback, highest priority first.
   *
   * @return true if every callback accepted the configuration
   */
  public boolean callProcessFileCallBacks() {
    List<Callback> ordered = new ArrayList<>(callbacks);
    ordered.sort(
        Comparator.comparingInt(Callback::priority).reversed().thenComparingLong(Callback::order));
    boolean ok = true;
    for (Callback c : ordered) {
      try {
        if (!c.cb().getAsBoolean()) {
          log.warn(
              "a configuration callback (priority {}) rejected the configuration", c.priority());
          ok = false;
        }
      } catch (RuntimeException e) {
        log.error("a configuration callback (priority {}) threw", c.priority, e);
        ok = false;
      }
    }
    return ok;
  }

  // ------------------------------------------------------------------ loading

  /**
   * Loads a configuration file: every known parameter in it takes the file's value, then the
   * process-file callbacks run.
   *
   * @throws ArConfigException if a line is malformed or a value out of bounds ("file:line: ..."; no
   *     value changes), or if a callback rejected the configuration (values stay set)
   * @throws IOException if the file cannot be read
   */
  public ParseResult parseFile(Path file) throws ArConfigException, IOException {
    ParamFile pf;
    try {
      pf = ParamFile.read(file);
    } catch (ParamFormatException e) {
      throw new ArConfigException(e.getSourceName(), e.getLine(), stripWhere(e), e);
    }
    return apply(pf);
  }

  /** As {@link #parseFile}, from text already in memory. */
  public ParseResult parseText(String text, String sourceName) throws ArConfigException {
    ParamFile pf;
    try {
      pf = ParamFile.parse(text, sourceName);
    } catch (ParamFormatException e) {
      throw new ArConfigException(e.getSourceName(), e.getLine(), stripWhere(e), e);
    }
    return apply(pf);
  }

  private static String stripWhere(ParamFormatException e) {
    String m = e.getMessage();
    String prefix = e.getSourceName() + ":" + e.getLine() + ": ";
    return m.startsWith(prefix) ? m.substring(prefix.length()) : m;
  }

  private ParseResult apply(ParamFile pf) throws ArConfigException {
    String source = pf.getSourceName();
    List<String> warnings = new ArrayList<>();
    Set<String> unknownSections = new HashSet<>();
    Map<ArConfigArg, Object> values = new LinkedHashMap<>();
    ArConfigException firstError = null;
    int errors = 0;
    synchronized (this) {
      for (ParamFile.Entry e : pf.entries()) {
        if (e.section().isEmpty() && e.keyword().equalsIgnoreCase("ConfigVersion")) {
          continue;
        }
        Optional<ArConfigArg> arg;
        if (e.section().isEmpty()) {
          arg = findParam(e.keyword());
        } else {
          Optional<ArConfigSection> s = findSection(e.section());
          if (s.isEmpty()) {
            if (unknownSections.add(e.section().toLowerCase(Locale.ROOT))) {
              warnings.add(
                  e.where() + ": unknown section '" + e.section() + "'; its lines are ignored");
            }
            continue;
          }
          arg = s.get().findParam(e.keyword());
        }
        if (arg.isEmpty()) {
          warnings.add(
              e.where()
                  + ": unknown parameter '"
                  + e.keyword()
                  + "'"
                  + (e.section().isEmpty() ? "" : " in section '" + e.section() + "'")
                  + "; it is ignored (check the spelling)");
          continue;
        }
        try {
          values.put(arg.get(), arg.get().parse(e.value()));
        } catch (IllegalArgumentException ex) {
          errors++;
          if (firstError == null) {
            firstError = new ArConfigException(source, e.line(), ex.getMessage(), ex);
          }
        }
      }
    }
    if (firstError != null) {
      if (errors == 1) {
        throw firstError;
      }
      throw new ArConfigException(
          source,
          firstError.getLine(),
          stripLocation(firstError)
              + " (and "
              + (errors - 1)
              + " more bad value"
              + (errors > 2 ? "s" : "")
              + "; nothing was applied)",
          firstError);
    }
    for (String w : warnings) {
      log.warn(w);
    }
    int changed = 0;
    for (Map.Entry<ArConfigArg, Object> v : values.entrySet()) {
      if (v.getKey().setValueFromTyped(v.getValue())) {
        changed++;
      }
    }
    if (!callProcessFileCallBacks()) {
      throw new ArConfigException(
          source,
          0,
          "the values were loaded but a module rejected the new configuration; see the log for"
              + " which and why");
    }
    return new ParseResult(source, values.size(), changed, warnings);
  }

  private static String stripLocation(ArConfigException e) {
    String m = e.getMessage();
    String prefix = e.getSourceName() + ":" + e.getLine() + ": ";
    return m.startsWith(prefix) ? m.substring(prefix.length()) : m;
  }

  /**
   * Sets one parameter from text, as a command line's {@code -name value} does, then runs the
   * process-file callbacks.
   *
   * @param paramName the parameter (first match in any section, case-insensitive)
   * @throws IllegalArgumentException if there is no such parameter or the value is bad
   */
  public void setParamFromText(String paramName, String text) {
    ArConfigArg a =
        findParam(paramName)
            .orElseThrow(
                () ->
                    new IllegalArgumentException(
                        "no configuration parameter called '"
                            + paramName
                            + "'; known ones: "
                            + allParamNames()));
    a.setValueFromText(text);
    callProcessFileCallBacks();
  }

  private List<String> allParamNames() {
    List<String> names = new ArrayList<>();
    for (ArConfigSection s : sections) {
      for (ArConfigArg a : s.getParams()) {
        names.add(a.getName());
      }
    }
    return names;
  }

  // ------------------------------------------------------------------ saving

  /**
   * Writes every section and parameter to {@code file}, in a form {@link #parseFile} reads. The
   * file is ISO-8859-1 (Latin-1), as ARIA's are; characters outside it in comments become '?'.
   */
  public void writeFile(Path file) throws IOException {
    // OutputStreamWriter replaces unmappable characters instead of failing.
    try (Writer w =
        new java.io.BufferedWriter(
            new java.io.OutputStreamWriter(
                Files.newOutputStream(file), StandardCharsets.ISO_8859_1))) {
      write(w);
    }
  }

  /** Writes the configuration as text. */
  public void write(Writer out) throws IOException {
    out.write("; JAria configuration: one 'Name value ; comment' per line, grouped in sections\n");
    for (ArConfigSection s : sections) {
      out.write("\nSection " + s.getName() + "\n");
      if (!s.getComment().isEmpty()) {
        out.write("; " + s.getComment() + "\n");
      }
      List<ArConfigArg> params = s.getParams();
      int width = 0;
      for (ArConfigArg a : params) {
        width = Math.max(width, a.getName().length() + 1 + a.getValueText().length());
      }
      for (ArConfigArg a : params) {
        StringBuilder line = new StringBuilder(a.getName()).append(' ').append(a.getValueText());
        String comment = a.getCommentText();
        if (!comment.isEmpty()) {
          while (line.length() < width + 2) {
            line.append(' ');
          }
          line.append("; ").append(comment.replace(';', ','));
        }
        out.write(line.toString().stripTrailing() + "\n");
      }
    }
  }

  /** The configuration as the text {@link #write} produces. */
  public String toText() {
    StringWriter w = new StringWriter();
    try {
      write(w);
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
    return w.toString();
  }

  @Override
  public String toString() {
    return "ArConfig" + sections;
  }
}
