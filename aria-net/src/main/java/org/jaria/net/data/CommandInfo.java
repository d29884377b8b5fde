package org.jaria.net.data;

import java.util.ArrayList;
import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.NetEncodable;

/**
 * A custom command a server offers ({@code "listCommands"}, ArNetworking's {@code
 * ArServerHandlerCommands}).
 *
 * @param name what to send in {@code "runCommand"}
 * @param description what it does
 * @param argumentDescription the arguments it takes ("" for none)
 */
public record CommandInfo(String name, String description, String argumentDescription)
    implements NetEncodable {

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(3).strToBuf(name).strToBuf(description).strToBuf(argumentDescription);
  }

  /** Reads what {@link #write} wrote. */
  public static CommandInfo read(ArNetPacket in) {
    int n = Fields.begin(in, 3, "a command");
    CommandInfo c = new CommandInfo(in.bufToStr(), in.bufToStr(), in.bufToStr());
    Fields.end(in, n, 3);
    return c;
  }

  /** Reads a list of commands (one array). */
  public static List<CommandInfo> readAll(ArNetPacket in) {
    int n = in.bufToArray();
    List<CommandInfo> l = new ArrayList<>(n);
    for (int i = 0; i < n; i++) {
      l.add(read(in));
    }
    return l;
  }
}
