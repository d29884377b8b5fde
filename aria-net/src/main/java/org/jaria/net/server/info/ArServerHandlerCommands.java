package org.jaria.net.server.info;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import org.jaria.net.ArNetPacket;
import org.jaria.net.data.CommandInfo;
import org.jaria.net.protocol.NetError;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.NetRequestException;
import org.jaria.net.server.TextLimits;
import org.jaria.net.server.Where;

/**
 * Custom commands (ArNetworking's {@code ArServerHandlerCommands}): a program adds named commands,
 * a monitor lists them and runs one by sending a request of the same name, with its arguments (any
 * simple values; the command receives them as text).
 *
 * <p>The lists have ArNetworking's layout ({@code byte2 count}, then {@code string name, string
 * description} per command): {@code "listCommands"} lists the commands without arguments, {@code
 * "listStringCommands"} those with arguments (an ARIA client sends them one string). {@code
 * "listStringCommands"} is registered by {@link #addStringCommandList}, so that the data numbers of
 * services registered before it stay as they were.
 *
 * <pre>{@code
 * ArServerHandlerCommands commands = new ArServerHandlerCommands(server);
 * commands.addCommand("resetOdometer", "sets the odometer to zero", robot::resetOdometer);
 * commands.addStringCommand("say", "logs a line", text -> log.info(text));
 * }</pre>
 *
 * <p>By default commands run on the robot's cycle, so they may touch the robot and its actions;
 * keep them short, or add them with {@link Where#WORKER}.
 */
public final class ArServerHandlerCommands {

  /** Command group of every custom command. */
  public static final String GROUP = "CustomCommands";

  /** A command's body: gets the arguments as text, returns a reply for the user ("" for none). */
  @FunctionalInterface
  public interface CommandHandler {
    /** Runs the command. */
    String run(List<String> args) throws Exception;
  }

  /** Return description of both lists, as ArNetworking gives it. */
  static final String LIST_RETURNS =
      "byte2: numberOfCommands, <repeats numberOfCommands> string: name, string: description";

  private final ArServerBase server;
  private final List<CommandInfo> commands = new CopyOnWriteArrayList<>();

  /** Registers {@code "listCommands"} with {@code server}. */
  public ArServerHandlerCommands(ArServerBase server) {
    this.server = server;
    server.addData(
        "listCommands",
        "Gets a list of simple commands that can be sent to the server",
        "none",
        LIST_RETURNS,
        GROUP,
        Where.WORKER,
        (client, request, reply) -> CommandInfo.writeList(reply, commandsTaking(false)));
  }

  /**
   * Registers {@code "listStringCommands"}: the commands that take arguments. Call it once, after
   * the services whose data numbers should not move.
   */
  public void addStringCommandList() {
    server.addData(
        "listStringCommands",
        "Gets a list of commands that can be sent to the server with string arguments",
        "none",
        LIST_RETURNS,
        GROUP,
        Where.WORKER,
        (client, request, reply) -> CommandInfo.writeList(reply, commandsTaking(true)));
  }

  private List<CommandInfo> commandsTaking(boolean arguments) {
    return getCommands().stream().filter(c -> c.takesArguments() == arguments).toList();
  }

  /** Adds a command without arguments, run on the robot's cycle. */
  public void addCommand(String name, String description, Runnable command) {
    addCommand(
        name,
        description,
        "",
        Where.CYCLE,
        args -> {
          command.run();
          return "";
        });
  }

  /** Adds a command taking one string (all arguments joined by spaces), run on the cycle. */
  public void addStringCommand(String name, String description, Consumer<String> command) {
    addCommand(
        name,
        description,
        "string: argumentToCommand",
        Where.CYCLE,
        args -> {
          command.accept(String.join(" ", args));
          return "";
        });
  }

  /**
   * Adds a command.
   *
   * @param argumentDescription its arguments, for people ("" for none)
   * @param where where it runs
   * @throws IllegalArgumentException if the name is already used by any data of the server
   */
  public void addCommand(
      String name,
      String description,
      String argumentDescription,
      Where where,
      CommandHandler handler) {
    // ArNetworking's commands return nothing (RETURN_NONE); a command that has something to say
    // answers with one string, which ARIA's clients ignore.
    server.addData(
        name,
        description,
        argumentDescription.isEmpty() ? "none" : argumentDescription,
        "none, or string: reply",
        GROUP,
        "RETURN_NONE",
        where,
        (client, request, reply) -> {
          String said = handler.run(argsAsText(request));
          if (said != null && !said.isEmpty()) {
            reply.strToBuf(TextLimits.clip(said, TextLimits.MAX_MESSAGE));
          }
        });
    commands.add(new CommandInfo(name, description, argumentDescription));
  }

  private static List<String> argsAsText(ArNetPacket p) throws NetRequestException {
    List<String> l = new ArrayList<>();
    while (p.hasMore()) {
      String a = p.bufToStr();
      if (a.length() > TextLimits.MAX_VALUE) {
        throw new NetRequestException(
            NetError.BAD_ARGUMENTS,
            "a command's argument has at most " + TextLimits.MAX_VALUE + " characters");
      }
      l.add(a);
    }
    return l;
  }

  /** The commands added so far. */
  public List<CommandInfo> getCommands() {
    return List.copyOf(commands);
  }
}
