package org.jaria.classroom.grading;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.Properties;
import java.util.Set;
import java.util.TreeSet;

/**
 * The words of the checks in one language: a catalogue of sentences with numbered holes ({@code
 * {0}}, {@code {1}}, ...) read from {@code checks_LANG.properties} beside this class. Every
 * assignment writes its check names and messages through it, so a grade made in Spanish says
 * nothing in English.
 */
public final class Texts {

  /** The languages there is a catalogue for. */
  public static final Set<String> LANGUAGES = Set.of("en", "es");

  private static final Texts ENGLISH = load("en");
  private static final Texts SPANISH = load("es");

  private final String lang;
  private final Properties entries;

  private Texts(String lang, Properties entries) {
    this.lang = lang;
    this.entries = entries;
  }

  /** English. */
  public static Texts english() {
    return ENGLISH;
  }

  /**
   * The catalogue of {@code lang}.
   *
   * @throws IllegalArgumentException if there is none ("en" and "es" exist)
   */
  public static Texts of(String lang) {
    return switch (lang) {
      case "en" -> ENGLISH;
      case "es" -> SPANISH;
      default ->
          throw new IllegalArgumentException("no check texts in '" + lang + "': use en or es");
    };
  }

  /** The language, "en" or "es". */
  public String lang() {
    return lang;
  }

  /** Whether the catalogue has sentence {@code key}. */
  public boolean has(String key) {
    return entries.getProperty(key) != null;
  }

  /** The keys of the catalogue. */
  public Set<String> keys() {
    return new TreeSet<>(entries.stringPropertyNames());
  }

  /**
   * The sentence {@code key} with {@code {i}} replaced by {@code args[i]}.
   *
   * @throws IllegalArgumentException if the catalogue has no such sentence (a bug of the grader)
   */
  public String get(String key, Object... args) {
    String s = entries.getProperty(key);
    if (s == null) {
      throw new IllegalArgumentException("no text '" + key + "' in checks_" + lang + ".properties");
    }
    for (int i = 0; i < args.length; i++) {
      s = s.replace("{" + i + "}", String.valueOf(args[i]));
    }
    return s;
  }

  /**
   * This catalogue and the sentences of a pack's own: {@code baseName_LANG.properties} beside
   * {@code anchor} (its own sentences win where a key is in both). A pack without a catalogue in
   * this language speaks English for its own sentences.
   *
   * @throws IllegalStateException if the pack has not even an English catalogue
   */
  public Texts with(Class<?> anchor, String baseName) {
    Properties p = new Properties();
    p.putAll(entries);
    InputStream in = anchor.getResourceAsStream(baseName + "_" + lang + ".properties");
    if (in == null) {
      in = anchor.getResourceAsStream(baseName + "_en.properties");
    }
    if (in == null) {
      throw new IllegalStateException(
          baseName
              + "_en.properties is missing beside "
              + anchor.getName()
              + ": a pack's sentences need at least an English catalogue");
    }
    try (InputStream s = in) {
      p.load(new InputStreamReader(s, StandardCharsets.UTF_8));
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
    return new Texts(lang, p);
  }

  private static Texts load(String lang) {
    String name = "checks_" + lang + ".properties";
    Properties p = new Properties();
    try (InputStream in = Texts.class.getResourceAsStream(name)) {
      if (in == null) {
        throw new IllegalStateException(name + " is missing from the classroom jar");
      }
      p.load(new InputStreamReader(in, StandardCharsets.UTF_8));
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
    return new Texts(lang, p);
  }
}
