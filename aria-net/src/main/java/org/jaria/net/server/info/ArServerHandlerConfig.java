package org.jaria.net.server.info;

import java.util.ArrayList;
import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.NetEncodable;
import org.jaria.net.data.ConfigSection;
import org.jaria.net.provider.ConfigRegistry;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.NetRequestException;
import org.jaria.net.server.PolledPublication;
import org.jaria.net.server.Where;

/**
 * The robot program's configuration for clients (ArNetworking's {@code ArServerHandlerConfig}):
 * {@code "getConfigBySections"} (published: subscribe slowly to hear of changes) and {@code
 * "setConfig"}, which sets parameters from text and answers which ones were refused and why.
 */
public final class ArServerHandlerConfig {

  /** The sections as one publishable value. */
  private record Sections(List<ConfigSection> sections) implements NetEncodable {
    @Override
    public void write(ArNetPacket out) {
      ConfigSection.writeAll(out, sections);
    }
  }

  /** Registers the configuration data with {@code server}. */
  public ArServerHandlerConfig(ArServerBase server, ConfigRegistry config) {
    server.addPublishedData(
        "getConfigBySections",
        "every configuration section with its parameters",
        "array of ConfigSection [name, comment, [[name, type, value, default, min, max,"
            + " description]...]]",
        "ConfigEditing",
        PolledPublication.of(() -> new Sections(config.getSections())));
    server.addData(
        "setConfig",
        "sets parameters from text; replies with the refusals (empty: all set)",
        "array of [string section, string name, string value]",
        "array of string: one message per refused parameter",
        "ConfigEditing",
        Where.WORKER,
        (client, request, reply) -> {
          int n = request.bufToArray();
          List<String> errors = new ArrayList<>();
          for (int i = 0; i < n; i++) {
            int k = request.bufToArray();
            String section = request.bufToStr();
            String name = request.bufToStr();
            String value = request.bufToStr();
            if (k != 3) {
              throw new NetRequestException(
                  org.jaria.net.protocol.NetError.BAD_ARGUMENTS, "each parameter needs 3 strings");
            }
            String err = config.setParam(section, name, value);
            if (err != null) {
              errors.add(err);
            }
          }
          reply.arrayToBuf(errors.size());
          for (String e : errors) {
            reply.strToBuf(e);
          }
        });
  }
}
