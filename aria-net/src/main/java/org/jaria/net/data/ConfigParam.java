package org.jaria.net.data;

import org.jaria.net.ArNetPacket;
import org.jaria.net.NetEncodable;

/**
 * One configuration parameter as clients see it (ArConfig's {@code ArConfigArg}), values as text.
 *
 * @param name the parameter's name
 * @param type "INT", "DOUBLE", "BOOL", "STRING" (or another type name of the registry)
 * @param value the current value
 * @param defaultValue the default value
 * @param min the lowest allowed value, "" if none
 * @param max the highest allowed value, "" if none
 * @param description what it does
 */
public record ConfigParam(
    String name,
    String type,
    String value,
    String defaultValue,
    String min,
    String max,
    String description)
    implements NetEncodable {

  private static final int FIELDS = 7;

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(FIELDS)
        .strToBuf(name)
        .strToBuf(type)
        .strToBuf(value)
        .strToBuf(defaultValue)
        .strToBuf(min)
        .strToBuf(max)
        .strToBuf(description);
  }

  /** Reads what {@link #write} wrote. */
  public static ConfigParam read(ArNetPacket in) {
    int n = Fields.begin(in, FIELDS, "a configuration parameter");
    ConfigParam p =
        new ConfigParam(
            in.bufToStr(),
            in.bufToStr(),
            in.bufToStr(),
            in.bufToStr(),
            in.bufToStr(),
            in.bufToStr(),
            in.bufToStr());
    Fields.end(in, n, FIELDS);
    return p;
  }
}
