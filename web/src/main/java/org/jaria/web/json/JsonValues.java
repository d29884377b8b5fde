package org.jaria.web.json;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Reads a JSON text into plain Java values: {@code Map<String, Object>} for objects, {@code
 * List<Object>} for arrays, {@code String}, {@code Double} or {@code Long} for numbers, {@code
 * Boolean}, and {@code null}. Within {@link Json}'s limits, and at most {@value #MAX_VALUES} values
 * in all, so a small message cannot make a large structure.
 */
public final class JsonValues {

  /** Most values (objects, arrays, strings, numbers...) one text may hold. */
  public static final int MAX_VALUES = 4096;

  /** The text was not JSON, or was JSON over a limit. */
  public static final class BadJson extends Exception {
    private static final long serialVersionUID = 1L;

    BadJson(String message, Throwable cause) {
      super(message, cause);
    }
  }

  private JsonValues() {}

  /**
   * The value of {@code text}.
   *
   * @throws BadJson if it is not one JSON value within the limits
   */
  public static Object read(String text) throws BadJson {
    return read(text, Json.factory(), MAX_VALUES);
  }

  /**
   * The value of {@code text}, read with another factory's limits and at most {@code maxValues}
   * values (for text that does not come from the network, such as the server's own messages in
   * tests).
   *
   * @throws BadJson if it is not one JSON value within the limits
   */
  public static Object read(
      String text, com.fasterxml.jackson.core.JsonFactory factory, int maxValues) throws BadJson {
    try (JsonParser p = factory.createParser(text)) {
      int[] budget = {maxValues};
      JsonToken t = p.nextToken();
      if (t == null) {
        throw new BadJson("empty message", null);
      }
      Object v = value(p, t, budget);
      if (p.nextToken() != null) {
        throw new BadJson("text after the JSON value", null);
      }
      return v;
    } catch (IOException e) {
      throw new BadJson("not JSON: " + firstLine(e.getMessage()), e);
    }
  }

  /** Jackson's messages add the source location on further lines; the first says what is wrong. */
  private static String firstLine(String s) {
    if (s == null) {
      return "unreadable";
    }
    int nl = s.indexOf('\n');
    return nl < 0 ? s : s.substring(0, nl);
  }

  private static Object value(JsonParser p, JsonToken t, int[] budget) throws IOException, BadJson {
    if (t == null) {
      throw new BadJson("the message ends inside a value", null);
    }
    if (--budget[0] < 0) {
      throw new BadJson("more than " + MAX_VALUES + " values in one message", null);
    }
    switch (t) {
      case START_OBJECT -> {
        Map<String, Object> m = new LinkedHashMap<>();
        for (JsonToken k = p.nextToken(); k != JsonToken.END_OBJECT; k = p.nextToken()) {
          String name = p.currentName();
          m.put(name, value(p, p.nextToken(), budget));
        }
        return m;
      }
      case START_ARRAY -> {
        List<Object> l = new ArrayList<>();
        for (JsonToken k = p.nextToken(); k != JsonToken.END_ARRAY; k = p.nextToken()) {
          l.add(value(p, k, budget));
        }
        return l;
      }
      case VALUE_STRING -> {
        return p.getText();
      }
      case VALUE_NUMBER_INT -> {
        return p.getNumberType() == JsonParser.NumberType.BIG_INTEGER
            ? (Object) p.getDoubleValue()
            : (Object) p.getLongValue();
      }
      case VALUE_NUMBER_FLOAT -> {
        return p.getDoubleValue();
      }
      case VALUE_TRUE -> {
        return true;
      }
      case VALUE_FALSE -> {
        return false;
      }
      case VALUE_NULL -> {
        return null;
      }
      default -> throw new BadJson("unexpected " + t, null);
    }
  }
}
