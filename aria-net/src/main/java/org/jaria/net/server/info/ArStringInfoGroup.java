package org.jaria.net.server.info;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BooleanSupplier;
import java.util.function.DoubleSupplier;
import java.util.function.IntSupplier;
import java.util.function.Supplier;
import org.jaria.net.data.InfoStrings;

/**
 * Labelled values a program wants its operators to see (ARIA's {@code ArStringInfoGroup}, thesis
 * §5.1.31): each entry is a label, a maximum length and a function giving the value now. {@link
 * ArServerInfoStrings} serves the table to clients, who show it next to the robot's state.
 *
 * <pre>{@code
 * ArStringInfoGroup info = new ArStringInfoGroup();
 * info.addStringInt("Motor Packet Count", 10, robot::getMotorPacCount);
 * info.addStringDouble("Localization Score", 8, loc::getLocalizationScore, "%.03f");
 * }</pre>
 *
 * <p>The functions are called from the server's publisher thread, at most at the clients' rates:
 * they must be thread-safe and quick (read a volatile, call a thread-safe getter). One that throws
 * shows "error".
 */
public final class ArStringInfoGroup {

  private record Entry(String label, int maxLength, Supplier<String> value) {}

  private final List<Entry> entries = new CopyOnWriteArrayList<>();

  /** Adds a text value. */
  public void addStringString(String label, int maxLength, Supplier<String> value) {
    entries.add(new Entry(label, maxLength, value));
  }

  /** Adds an integer value. */
  public void addStringInt(String label, int maxLength, IntSupplier value) {
    addStringInt(label, maxLength, value, "%d");
  }

  /** Adds an integer value shown with a {@link String#format} pattern. */
  public void addStringInt(String label, int maxLength, IntSupplier value, String format) {
    addStringString(label, maxLength, () -> String.format(Locale.ROOT, format, value.getAsInt()));
  }

  /** Adds a number shown with a {@link String#format} pattern ("%.2f"). */
  public void addStringDouble(String label, int maxLength, DoubleSupplier value, String format) {
    addStringString(
        label, maxLength, () -> String.format(Locale.ROOT, format, value.getAsDouble()));
  }

  /** Adds a yes/no value ("true"/"false"). */
  public void addStringBool(String label, int maxLength, BooleanSupplier value) {
    addStringString(label, maxLength, () -> Boolean.toString(value.getAsBoolean()));
  }

  /** Removes every entry with this label. */
  public void remove(String label) {
    entries.removeIf(e -> e.label().equals(label));
  }

  /**
   * Writes ArNetworking's {@code "getStringsInfo"} layout: uByte2 count; per entry its label and
   * its maximum length (uByte2, 0 for none).
   */
  public void writeInfo(org.jaria.net.ArNetPacket out) {
    List<Entry> l = List.copyOf(entries);
    out.uByte2ToBuf(l.size());
    for (Entry e : l) {
      out.strToBuf(e.label()).uByte2ToBuf(Math.max(0, Math.min(e.maxLength(), 0xffff)));
    }
  }

  /** Evaluates every entry now (values cut to their maximum lengths). */
  public InfoStrings evaluate() {
    List<String> labels = new ArrayList<>();
    List<String> values = new ArrayList<>();
    for (Entry e : entries) {
      String v;
      try {
        v = String.valueOf(e.value().get());
      } catch (RuntimeException ex) {
        v = "error";
      }
      if (e.maxLength() > 0 && v.length() > e.maxLength()) {
        v = v.substring(0, e.maxLength());
      }
      labels.add(e.label());
      values.add(v);
    }
    return new InfoStrings(labels, values);
  }
}
