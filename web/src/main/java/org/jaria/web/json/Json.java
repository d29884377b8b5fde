package org.jaria.web.json;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.StreamReadConstraints;
import com.fasterxml.jackson.core.util.ByteArrayBuilder;
import java.io.IOException;
import java.io.UncheckedIOException;

/**
 * The JSON factory of the web view, with limits for text that comes from the network: at most
 * {@value #MAX_DEPTH} levels of nesting, numbers of at most {@value #MAX_NUMBER_LENGTH} digits and
 * strings of at most {@value #MAX_STRING_LENGTH} characters. A message over a limit is a parse
 * error like any other malformed JSON.
 */
public final class Json {

  /** Deepest nesting a client's message may have. */
  public static final int MAX_DEPTH = 16;

  /** Longest number a client's message may hold, characters. */
  public static final int MAX_NUMBER_LENGTH = 40;

  /** Longest string a client's message may hold, characters. */
  public static final int MAX_STRING_LENGTH = 4096;

  private static final JsonFactory FACTORY =
      JsonFactory.builder()
          .streamReadConstraints(
              StreamReadConstraints.builder()
                  .maxNestingDepth(MAX_DEPTH)
                  .maxNumberLength(MAX_NUMBER_LENGTH)
                  .maxStringLength(MAX_STRING_LENGTH)
                  .build())
          .build();

  private Json() {}

  /** The factory (thread-safe). */
  public static JsonFactory factory() {
    return FACTORY;
  }

  /** Something that writes one JSON value. */
  @FunctionalInterface
  public interface Body {
    /** Writes the value. */
    void write(JsonGenerator g) throws IOException;
  }

  /** The UTF-8 bytes of the value {@code body} writes. */
  public static byte[] bytes(Body body) {
    ByteArrayBuilder out = new ByteArrayBuilder(256);
    try (JsonGenerator g = FACTORY.createGenerator(out)) {
      body.write(g);
    } catch (IOException e) {
      // Writing to memory fails only on a bug in the writer (say, an unbalanced object).
      throw new UncheckedIOException("could not write JSON: " + e.getMessage(), e);
    }
    return out.toByteArray();
  }

  /** The value {@code body} writes, as a string. */
  public static String string(Body body) {
    return new String(bytes(body), java.nio.charset.StandardCharsets.UTF_8);
  }
}
