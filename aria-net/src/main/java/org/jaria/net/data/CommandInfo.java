package org.jaria.net.data;

import java.util.ArrayList;
import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;

/**
 * A custom command a server offers (ArNetworking's {@code ArServerHandlerCommands}), as listed by
 * {@code "listCommands"} (commands without arguments) and {@code "listStringCommands"} (commands
 * with arguments).
 *
 * @param name the data name to send to run it
 * @param description what it does
 * @param argumentDescription the arguments it takes ("" for none)
 */
public record CommandInfo(String name, String description, String argumentDescription) {

  /** Argument description of the commands {@code "listStringCommands"} lists. */
  public static final String STRING_ARGUMENT = "string: argumentToCommand";

  /** Whether it takes arguments. */
  public boolean takesArguments() {
    return !argumentDescription.isEmpty();
  }

  /**
   * Writes ArNetworking's list layout: {@code byte2 count}, then {@code string name, string
   * description} per command.
   */
  public static void writeList(ArNetPacket out, List<CommandInfo> commands) {
    out.byte2ToBuf(commands.size());
    for (CommandInfo c : commands) {
      out.strToBuf(c.name()).strToBuf(c.description());
    }
  }

  /**
   * Reads a list {@link #writeList} wrote (or ARIA's server sent).
   *
   * @param takesArguments whether it is the list of commands with arguments ({@code
   *     "listStringCommands"}); their argument description is then {@link #STRING_ARGUMENT}
   */
  public static List<CommandInfo> readList(ArNetPacket in, boolean takesArguments) {
    int n = in.bufToByte2();
    if (n < 0) {
      throw new ArNetPacketException("a command list of " + n + " commands");
    }
    List<CommandInfo> l = new ArrayList<>(Math.min(n, 1024));
    for (int i = 0; i < n; i++) {
      l.add(new CommandInfo(in.bufToStr(), in.bufToStr(), takesArguments ? STRING_ARGUMENT : ""));
    }
    return l;
  }
}
