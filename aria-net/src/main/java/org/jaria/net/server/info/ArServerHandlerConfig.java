package org.jaria.net.server.info;

import org.jaria.net.ArNetPacket;
import org.jaria.net.data.ConfigLayout;
import org.jaria.net.data.ConfigSection;
import org.jaria.net.provider.ConfigRegistry;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.Where;

/**
 * The robot program's configuration for clients (ArNetworking's {@code ArServerHandlerConfig}), in
 * ArNetworking's layouts so ARIA's {@code ArClientHandlerConfig} reads and sets it: {@code
 * "getConfigBySections"} answers one packet per section (see {@link ConfigLayout}) ended by an
 * empty packet; {@code "setConfig"} takes pairs of strings (parameter, value), where the parameter
 * {@code "Section"} names the section of the pairs after it, sets every parameter it can and
 * answers one string: empty when all were set, otherwise the first refusal.
 */
public final class ArServerHandlerConfig {

  /** Registers the configuration data with {@code server}. */
  public ArServerHandlerConfig(ArServerBase server, ConfigRegistry config) {
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
            if (name.equalsIgnoreCase("Section")) {
              section = value;
              continue;
            }
            String err = config.setParam(section, name, value);
            if (err != null && first.isEmpty()) {
              first = err;
            }
          }
          reply.strToBuf(first);
        });
  }
}
