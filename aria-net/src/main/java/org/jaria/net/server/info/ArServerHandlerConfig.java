package org.jaria.net.server.info;

import org.jaria.net.ArNetPacket;
import org.jaria.net.data.ConfigDefaultsLayout;
import org.jaria.net.data.ConfigLayout;
import org.jaria.net.data.ConfigSection;
import org.jaria.net.provider.ConfigRegistry;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.TextLimits;
import org.jaria.net.server.Where;

/**
 * The robot program's configuration for clients (ArNetworking's {@code ArServerHandlerConfig}), in
 * ArNetworking's layouts so ARIA's {@code ArClientHandlerConfig} reads and sets it: {@code
 * "getConfigBySections"} answers one packet per section (see {@link ConfigLayout}) ended by an
 * empty packet; {@code "setConfig"} takes pairs of strings (parameter, value), where the parameter
 * {@code "Section"} names the section of the pairs after it, sets every parameter it can and
 * answers one string: empty when all were set, otherwise the first refusal. After a {@code
 * "setConfig"}, {@code "configUpdated"} (an empty packet) goes to every other client that asked for
 * it, once {@link #addDefaultServerCommands} has registered it with {@code "getConfigDefaults"}.
 */
public final class ArServerHandlerConfig {

  private final ArServerBase server;
  private final ConfigRegistry config;

  /** Registers the configuration data with {@code server}. */
  public ArServerHandlerConfig(ArServerBase server, ConfigRegistry config) {
    this.server = server;
    this.config = config;
    server.addData(
        "getConfigBySections",
        "gets the configuration, one packet per section",
        "none",
        "per section: byte 'S', string name, string comment, then per parameter byte 'P', string"
            + " name, string description, byte priority, byte type (b, i, d, s) and its values,"
            + " string display hint; an empty packet ends",
        "ConfigEditing",
        "RETURN_UNTIL_EMPTY",
        Where.WORKER,
        (client, request, reply) -> {
          int cmd = server.findCommandFromName("getConfigBySections");
          for (ConfigSection s : config.getSections()) {
            ArNetPacket p = new ArNetPacket(cmd);
            ConfigLayout.writeSection(p, s);
            client.sendPacketTcp(p);
          }
          // The (empty) reply packet the server sends next ends the answer.
        });
    server.addData(
        "setConfig",
        "sets parameters from text",
        "repeating pairs of strings: parameter name and value; the name Section starts a section",
        "string: empty if all were set, else the first refusal",
        "ConfigEditing",
        "RETURN_SINGLE|IDLE_PACKET",
        Where.WORKER,
        (client, request, reply) -> {
          String section = "";
          String first = "";
          while (request.hasMore()) {
            String name = request.bufToStr();
            String value = request.bufToStr();
            String err;
            if (name.length() > TextLimits.MAX_NAME || value.length() > TextLimits.MAX_VALUE) {
              // Nothing this long is kept, nor sent to every client that reads the config.
              err =
                  TextLimits.clip(name, 40)
                      + ": names have at most "
                      + TextLimits.MAX_NAME
                      + " characters and values at most "
                      + TextLimits.MAX_VALUE;
              section = name.equalsIgnoreCase("Section") ? "" : section;
            } else if (name.equalsIgnoreCase("Section")) {
              section = value;
              continue;
            } else {
              err = config.setParam(section, name, value);
            }
            if (err != null && first.isEmpty()) {
              first = err;
            }
          }
          reply.strToBuf(TextLimits.clip(first, TextLimits.MAX_MESSAGE));
          // As ArNetworking: every setConfig tells the other clients to read the config again.
          server.broadcastPacketTcpWithExclusion(new ArNetPacket(), "configUpdated", client);
        });
  }

  /**
   * Registers {@code "getConfigDefaults"} (the defaults in {@link ConfigDefaultsLayout}), {@code
   * "configDefaultsUpdated"} and {@code "configUpdated"}: ArNetworking's names and layouts. They
   * are registered separately from the constructor so that a server can add them after its other
   * data and keep the numbers clients know.
   */
  public void addDefaultServerCommands() {
    server.addData(
        "getConfigDefaults",
        "Gets the config default values ",
        "string: section to load, empty string means get the whole thing",
        "repeating strings that are the parameters and arguments to parse, but use"
            + " ArClientHandlerConfig to handle this if you want",
        "ConfigEditing",
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> {
          String section = request.hasMore() ? request.bufToStr() : "";
          ConfigDefaultsLayout.write(reply, config.getSections(), section);
        });
    server.addData(
        "configDefaultsUpdated",
        "Gets sent when the config defaults are updated",
        "none",
        "none",
        "ConfigEditing",
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> {});
    server.addData(
        "configUpdated",
        "gets sent when the config is updated",
        "none",
        "none",
        "ConfigEditing",
        "RETURN_SINGLE",
        Where.WORKER,
        (client, request, reply) -> {});
  }
}
